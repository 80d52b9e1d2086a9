package org.trajeval.pipeline;

import java.nio.file.Path;
import java.util.Objects;
import org.trajeval.core.options.SettingValues;

/**
 * One run ready to score: its identity, the two trajectory files (already checked to lie inside
 * the bundle), its metric settings, and where it came from.
 *
 * @param metadata run identity
 * @param reference reference (ground truth) trajectory file
 * @param estimate estimated trajectory file
 * @param settings checked evaluation settings
 * @param source where the run came from, for logs and the report (bundle name, or topic-partition@offset)
 * @param folder the bundle folder path settings (ref_times, est_times) are resolved in, or
 *     {@code null} when the run has none (a bare pair, an inline event)
 * @param plot true to draw the run's figures beside its report (run.yaml {@code plot: true})
 */
public record RunJob(RunMetadata metadata, Path reference, Path estimate, SettingValues settings, String source,
        Path folder, boolean plot) {
    /** @throws NullPointerException on a missing component */
    public RunJob {
        Objects.requireNonNull(metadata, "metadata");
        Objects.requireNonNull(reference, "reference");
        Objects.requireNonNull(estimate, "estimate");
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(source, "source");
    }

    /** A run without figures. */
    public RunJob(RunMetadata metadata, Path reference, Path estimate, SettingValues settings, String source,
            Path folder) {
        this(metadata, reference, estimate, settings, source, folder, false);
    }

    /** A run without a bundle folder. */
    public RunJob(RunMetadata metadata, Path reference, Path estimate, SettingValues settings, String source) {
        this(metadata, reference, estimate, settings, source, null);
    }
}
