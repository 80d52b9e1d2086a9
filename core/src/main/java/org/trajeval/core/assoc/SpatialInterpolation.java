package org.trajeval.core.assoc;

import org.trajeval.core.geom.Rotations;
import org.trajeval.core.traj.PoseSequence;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * SE(3) interpolation: positions linear in time, rotations by slerp of the quaternions along
 * the shorter arc (as evo's {@code PoseTrajectory3D.interpolate}).
 */
final class SpatialInterpolation {
    private SpatialInterpolation() {
    }

    /** Interpolates at increasing stamps inside the trajectory's span (s). */
    static PoseSequence at(SpatialTrajectory ref, double[] stamps) {
        return evoInterpolate(ref, stamps);
    }

    /**
     * evo's rule: segment = first pose with t >= query (clamped to [1, n-1]); fraction
     * f = (t - t_prev) / (t_next - t_prev) clamped to [0, 1]; position p_prev + f (p_next - p_prev);
     * rotation slerp(q_prev, q_next, f). Queries outside the span are clamped to the end poses.
     *
     * @param stamps increasing query times (s)
     */
    static PoseSequence evoInterpolate(SpatialTrajectory ref, double[] stamps) {
        int n = stamps.length;
        int nr = ref.size();
        double[] x = new double[n];
        double[] y = new double[n];
        double[] z = new double[n];
        double[] r = new double[9 * n];
        double[] q0 = new double[4];
        double[] q1 = new double[4];
        double[] q = new double[4];
        int idx = 0;
        for (int k = 0; k < n; k++) {
            double t = stamps[k];
            while (idx < nr && ref.t(idx) < t) {
                idx++;
            }
            int seg = Math.max(1, Math.min(nr - 1, idx));
            double tPrev = ref.t(seg - 1);
            double dt = ref.t(seg) - tPrev;
            double f = dt > 0.0 ? (t - tPrev) / dt : 0.0;
            f = Math.max(0.0, Math.min(1.0, f));
            x[k] = ref.x(seg - 1) + f * (ref.x(seg) - ref.x(seg - 1));
            y[k] = ref.y(seg - 1) + f * (ref.y(seg) - ref.y(seg - 1));
            z[k] = ref.z(seg - 1) + f * (ref.z(seg) - ref.z(seg - 1));
            ref.quaternion(seg - 1, q0);
            ref.quaternion(seg, q1);
            Rotations.slerp(q0, q1, f, q);
            Rotations.fromQuaternion(q[0], q[1], q[2], q[3], r, 9 * k);
        }
        return PoseSequence.of(x, y, z, r);
    }
}
