package org.trajeval.core.options;

import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.Trajectory;

/** What the pair of trajectories is, as far as the defaults care: planar SE(2) or SE(3). */
public enum DataKind {
    /** Both trajectories planar (t, x, y, yaw). */
    PLANAR,
    /** At least one trajectory carries full SE(3) poses. */
    SPATIAL;

    /** @return PLANAR when both are planar trajectories, else SPATIAL */
    public static DataKind of(Trajectory reference, Trajectory estimate) {
        return reference instanceof PlanarTrajectory && estimate instanceof PlanarTrajectory ? PLANAR : SPATIAL;
    }
}
