package org.trajeval.pipeline;

import java.util.Objects;
import org.trajeval.core.io.LoadedTrajectory;

/**
 * A run's two trajectories as read, each with the SHA-256 of its file's bytes taken in the same
 * pass ({@link LoadedTrajectory#sha256()}, null for a bag topic): the run's content hash is made
 * from these, so each input file is read once, and the bytes hashed are the bytes scored.
 *
 * @param reference the reference as read
 * @param estimate the estimate as read
 */
public record RunInputs(LoadedTrajectory reference, LoadedTrajectory estimate) {
    /** @throws NullPointerException on a missing trajectory */
    public RunInputs {
        Objects.requireNonNull(reference, "reference");
        Objects.requireNonNull(estimate, "estimate");
    }
}
