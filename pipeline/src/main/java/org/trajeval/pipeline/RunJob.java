package org.trajeval.pipeline;

import java.nio.file.Path;
import java.util.Objects;

/**
 * One run ready to score: its identity, the two trajectory files (already checked to lie inside
 * the bundle), its metric settings, and where it came from.
 *
 * @param metadata run identity
 * @param reference reference (ground truth) trajectory file
 * @param estimate estimated trajectory file
 * @param settings metric settings
 * @param source where the run came from, for logs and the report (bundle name, or topic-partition@offset)
 */
public record RunJob(RunMetadata metadata, Path reference, Path estimate, MetricSettings settings, String source) {
    /** @throws NullPointerException on a missing component */
    public RunJob {
        Objects.requireNonNull(metadata, "metadata");
        Objects.requireNonNull(reference, "reference");
        Objects.requireNonNull(estimate, "estimate");
        Objects.requireNonNull(settings, "settings");
        Objects.requireNonNull(source, "source");
    }
}
