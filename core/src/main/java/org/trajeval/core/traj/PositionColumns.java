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

    /**
     * @param n how many positions, from the first
     * @return the centroid {x, y, z} (m) of the first n positions: (1/n) sum_i p_i, each coordinate
     *     summed in index order
     */
    default double[] centroid(int n) {
        double mx = 0;
        double my = 0;
        double mz = 0;
        for (int i = 0; i < n; i++) {
            mx += x(i);
            my += y(i);
            mz += z(i);
        }
        return new double[] {mx / n, my / n, mz / n};
    }
}
