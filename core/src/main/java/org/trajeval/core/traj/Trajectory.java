package org.trajeval.core.traj;

/**
 * A time-stamped sequence of poses with non-decreasing timestamps (s; readers refuse
 * duplicates unless told to keep them, as evo does), stored column-wise
 * in primitive arrays. Either planar SE(2) ({@link PlanarTrajectory}: t, x, y, yaw) or full
 * SE(3) ({@link SpatialTrajectory}: t, position, unit quaternion).
 */
public sealed interface Trajectory extends PositionColumns permits PlanarTrajectory, SpatialTrajectory {

    /** @return number of poses */
    int size();

    /** @return timestamp of pose {@code i} (s) */
    double t(int i);

    /** @return x of pose {@code i} (m) */
    double x(int i);

    /** @return y of pose {@code i} (m) */
    double y(int i);

    /** @return z of pose {@code i} (m); 0 for a planar trajectory */
    double z(int i);

    /**
     * Writes the rotation matrix of pose {@code i} (row-major, body to world) into
     * {@code out[o..o+9)}: for a planar pose the rotation about +z by its yaw, exactly the matrix
     * {@link #toSpatial()} holds.
     */
    void rotation(int i, double[] out, int o);

    /** @return a copy of the timestamps (s) */
    double[] timestamps();

    /** @return this trajectory as SE(3): a planar pose becomes z = 0 and a rotation about +z by yaw */
    SpatialTrajectory toSpatial();

    /**
     * @return this trajectory projected onto the ground plane xy: z dropped, yaw = atan2(R10, R00)
     *     of the rotation matrix (the z angle of the static x-y-z Euler decomposition, as evo)
     */
    PlanarTrajectory toPlanar();

    /** @return the poses with indices in [from, to) */
    Trajectory slice(int from, int to);

    /**
     * @return the first index k in [from, to) with t(k) &gt;= t (s), or {@code to} when there is
     *     none; binary search, the timestamps being non-decreasing
     */
    default int firstAtOrAfter(double t, int from, int to) {
        int lo = from;
        int hi = to;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (t(mid) < t) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }
}
