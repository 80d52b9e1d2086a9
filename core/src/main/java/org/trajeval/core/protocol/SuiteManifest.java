package org.trajeval.core.protocol;

import java.util.List;
import java.util.Objects;
import org.trajeval.core.options.SettingValues;

/**
 * A benchmark described by one manifest: the protocol tuple Pi = (S, M, B, R) of the lesson's
 * section 4 (split policy in the sequences, metric set in {@code metrics} and {@code score},
 * budget, randomness in {@code seeds}) plus the methods under test and the failure definition.
 *
 * @param name benchmark (dataset) name
 * @param sequences the sequences, in manifest order
 * @param methods the methods, in manifest order
 * @param seeds the seed set Omega every method must be run with, ascending
 * @param evaluatedSplits the splits whose sequences are scored and compared
 * @param metrics how each run is read and evaluated (the settings table; a sequence or method may add more)
 * @param failure what counts as a failed run
 * @param score the normalised score (Proposition 3)
 * @param budget the compute budget (checked against {@code resources} when given)
 * @param resources path of the resources CSV (one row per run: wall time, peak memory), relative to the
 *     manifest's folder, or {@code null}
 */
public record SuiteManifest(String name, List<SequenceSpec> sequences, List<MethodSpec> methods, List<Long> seeds,
        List<Split> evaluatedSplits, SettingValues metrics, FailureDefinition failure, NormalisedScore score,
        Budget budget, String resources) {

    /** A manifest without a resources table. */
    public SuiteManifest(String name, List<SequenceSpec> sequences, List<MethodSpec> methods, List<Long> seeds,
            List<Split> evaluatedSplits, SettingValues metrics, FailureDefinition failure, NormalisedScore score,
            Budget budget) {
        this(name, sequences, methods, seeds, evaluatedSplits, metrics, failure, score, budget, null);
    }

    /** Name of the manifest format. */
    public static final String FORMAT = "trajeval.suite-manifest";
    /** Version of the manifest format this parser reads. */
    public static final int FORMAT_VERSION = 1;

    /** @throws NullPointerException on a missing component */
    public SuiteManifest {
        Objects.requireNonNull(name, "name");
        sequences = List.copyOf(sequences);
        methods = List.copyOf(methods);
        seeds = List.copyOf(seeds);
        evaluatedSplits = List.copyOf(evaluatedSplits);
        Objects.requireNonNull(metrics, "metrics");
        Objects.requireNonNull(failure, "failure");
        Objects.requireNonNull(score, "score");
        Objects.requireNonNull(budget, "budget");
    }

    /** @return the sequence with that id, or {@code null} */
    public SequenceSpec sequence(String id) {
        for (SequenceSpec s : sequences) {
            if (s.id().equals(id)) {
                return s;
            }
        }
        return null;
    }
}
