package org.trajeval.pipeline;

import java.util.Locale;
import java.util.Objects;
import org.trajeval.core.InputException;

/**
 * Why a run was put aside: the stage it failed in, a kind (the {@link org.trajeval.core.InputProblem}
 * in lower case for bad input, {@code internal} otherwise) and the one-line message the CLI would
 * print.
 *
 * @param stage where it failed
 * @param kind the kind of failure, e.g. {@code path_escapes}, {@code not_a_number}, {@code internal}
 * @param message one line naming the file, field and what was expected
 * @param badInput true when the input is at fault (retrying the same input fails again)
 */
public record RunFailure(Stage stage, String kind, String message, boolean badInput) {
    /** @throws NullPointerException on a missing component */
    public RunFailure {
        Objects.requireNonNull(stage, "stage");
        Objects.requireNonNull(kind, "kind");
        message = message == null ? kind : message.replace('\n', ' ').replace('\r', ' ');
    }

    /** @return the failure describing {@code e} thrown during {@code stage} */
    public static RunFailure of(Stage stage, RuntimeException e) {
        if (e instanceof InputException ie) {
            return new RunFailure(stage, ie.problem().name().toLowerCase(Locale.ROOT), ie.getMessage(), true);
        }
        if (e instanceof IllegalArgumentException || e instanceof java.io.UncheckedIOException) {
            return new RunFailure(stage, "bad_input", e.getMessage(), true);
        }
        return new RunFailure(stage, "internal", "internal error: " + e, false);
    }
}
