package org.trajeval.pipeline.dir;

import java.time.Duration;
import java.util.Objects;

/**
 * How the directory mode runs.
 *
 * @param workers threads scoring runs in parallel, >= 1
 * @param queueCapacity bundles claimed ahead of the workers, >= 0 (at most workers + queueCapacity
 *     bundles are in processing/ at once: the backpressure that keeps a large backlog on disk)
 * @param completion when a bundle counts as complete
 * @param quietTime how long a bundle without marker must be unchanged (MARKER_OR_QUIET)
 * @param scanInterval pause between two scans of incoming/ when it had nothing to do
 */
public record DirectoryOptions(int workers, int queueCapacity, Completion completion, Duration quietTime,
        Duration scanInterval) {
    /** @throws IllegalArgumentException on a value out of range */
    public DirectoryOptions {
        Objects.requireNonNull(completion, "completion");
        Objects.requireNonNull(quietTime, "quietTime");
        Objects.requireNonNull(scanInterval, "scanInterval");
        if (workers < 1 || queueCapacity < 0) {
            throw new IllegalArgumentException("workers must be >= 1 and queue_capacity >= 0, got " + workers + " and "
                    + queueCapacity);
        }
        if (quietTime.isNegative() || scanInterval.isNegative() || scanInterval.isZero()) {
            throw new IllegalArgumentException("quiet_time_s must be >= 0 and scan_interval_s > 0");
        }
    }

    /** @return 2 workers, 2 queued, marker completion, 60 s quiet time, 1 s scan interval */
    public static DirectoryOptions defaults() {
        return new DirectoryOptions(2, 2, Completion.MARKER, Duration.ofSeconds(60), Duration.ofSeconds(1));
    }
}
