package org.trajeval.core.batch;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.trajeval.core.options.SettingText;

/**
 * One row of a table of pairs to score in one process ({@code trajeval eval --batch}, or a Spark
 * job's rows): the two files, the row's own evaluation settings (named as in the options model,
 * {@code max_diff_s}, {@code alignment}, ...; they refine the job's settings) and every other column,
 * passed through to the summary unchanged.
 *
 * @param line the row's 1-based line in its table (0 when the row did not come from a file)
 * @param name the row's report name (its {@code name} column), or {@code null}: reports are then
 *     named after the line ({@code line-0007})
 * @param reference the reference file, as written
 * @param estimate the estimate file, as written
 * @param settings the row's settings as text (empty cells left out)
 * @param passThrough the other columns, in table order
 */
public record BatchPair(long line, String name, String reference, String estimate, List<SettingText> settings,
        Map<String, String> passThrough) {

    /** @throws NullPointerException without reference, estimate, settings or pass-through columns */
    public BatchPair {
        Objects.requireNonNull(reference, "reference");
        Objects.requireNonNull(estimate, "estimate");
        settings = List.copyOf(settings);
        passThrough = Collections.unmodifiableMap(new LinkedHashMap<>(passThrough));
    }

    /** @return the base name of the row's report file (without {@code .json}) */
    public String reportName() {
        return name != null ? name : String.format(java.util.Locale.ROOT, "line-%04d", line);
    }
}
