package org.trajeval.core.traj;

/**
 * Positions read by index, whatever holds them (a trajectory, associated poses, an interpolated
 * reference): what checks over positions (spreads, flatness) need, without copying them.
 */
public interface PositionColumns {
    /** @return x of position i (m) */
    double x(int i);

    /** @return y of position i (m) */
    double y(int i);

    /** @return z of position i (m) */
    double z(int i);
}
