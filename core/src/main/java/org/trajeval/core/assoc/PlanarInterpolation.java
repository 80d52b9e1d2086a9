package org.trajeval.core.assoc;

import org.trajeval.core.geom.Rotations;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.PoseSequence;

/**
 * The lesson's planar interpolation: x, y linear in time, yaw through its sine and cosine
 * (interpolate cos yaw and sin yaw linearly, then yaw = atan2(sin, cos)), which is continuous
 * across the +-pi cut.
 */
final class PlanarInterpolation {
    private PlanarInterpolation() {
    }

    /**
     * @param stamps query times inside the reference's span, increasing (s)
     * @return the interpolated poses, lifted to SE(3) (z = 0, rotation about +z)
     */
    static PoseSequence at(PlanarTrajectory ref, double[] stamps) {
        int n = stamps.length;
        double[] x = new double[n];
        double[] y = new double[n];
        double[] r = new double[9 * n];
        int seg = 1;
        int last = ref.size() - 1;
        for (int k = 0; k < n; k++) {
            double t = stamps[k];
            // first reference index with t(seg) >= t (merge walk: stamps increase)
            while (seg < last && ref.t(seg) < t) {
                seg++;
            }
            double t0 = ref.t(seg - 1);
            double f = (t - t0) / (ref.t(seg) - t0);
            f = Math.max(0.0, Math.min(1.0, f));
            x[k] = ref.x(seg - 1) + f * (ref.x(seg) - ref.x(seg - 1));
            y[k] = ref.y(seg - 1) + f * (ref.y(seg) - ref.y(seg - 1));
            double c0 = Math.cos(ref.yaw(seg - 1));
            double s0 = Math.sin(ref.yaw(seg - 1));
            double c = c0 + f * (Math.cos(ref.yaw(seg)) - c0);
            double s = s0 + f * (Math.sin(ref.yaw(seg)) - s0);
            Rotations.aboutZ(Math.atan2(s, c), r, 9 * k);
        }
        return PoseSequence.of(x, y, new double[n], r);
    }
}
