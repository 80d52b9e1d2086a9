package org.trajeval.core.protocol;

import java.util.List;
import java.util.Objects;
import org.trajeval.core.options.SettingText;

/**
 * One method (algorithm under test) of a suite manifest.
 *
 * @param name method name, unique in the suite ([A-Za-z0-9._-]+)
 * @param estimates path pattern of the estimate files relative to the manifest's folder, with the
 *     placeholders {@code {method}}, {@code {sequence}} and {@code {seed}}, e.g.
 *     {@code runs/{method}/{sequence}/seed{seed}.csv}
 * @param seeds the seeds this method was run with, ascending
 * @param settings evaluation settings of this method's runs on top of the suite's {@code metrics} and
 *     the sequence's (e.g. {@code est_format}, {@code est_times} with the same placeholders as
 *     {@code estimates}), in manifest order
 */
public record MethodSpec(String name, String estimates, List<Long> seeds, List<SettingText> settings) {
    /** @throws NullPointerException on a missing component */
    public MethodSpec {
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(estimates, "estimates");
        seeds = List.copyOf(seeds);
        settings = List.copyOf(settings);
    }

    /** @return the estimate path of one run: the pattern with its placeholders filled in */
    public String estimateFor(String sequenceId, long seed) {
        return fill(estimates, sequenceId, seed);
    }

    /** @return the pattern with {@code {method}}, {@code {sequence}} and {@code {seed}} filled in */
    public String fill(String pattern, String sequenceId, long seed) {
        return pattern.replace("{method}", name).replace("{sequence}", sequenceId)
                .replace("{seed}", Long.toString(seed));
    }
}
