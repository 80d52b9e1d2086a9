package org.trajeval.core.io;

import java.util.Objects;
import org.trajeval.core.traj.Trajectory;

/**
 * A trajectory together with where it came from.
 *
 * @param source the path as given by the user
 * @param format the format it was read as
 * @param formatReason why that format: "given" or what auto-detection saw
 * @param trajectory the poses
 * @param sha256 SHA-256 of the file's bytes, lower-case hex
 * @param indexTimestamps true when the file had no timestamps (KITTI without a times file) and
 *     t is the pose index (0, 1, 2, ... s)
 */
public record LoadedTrajectory(String source, TrajectoryFormat format, String formatReason, Trajectory trajectory,
        String sha256, boolean indexTimestamps) {
    /** @throws NullPointerException on a missing component */
    public LoadedTrajectory {
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(format, "format");
        Objects.requireNonNull(trajectory, "trajectory");
    }
}
