package org.trajeval.core.eval;

import org.trajeval.core.traj.SpatialTrajectory;

/** Test helper: applies p -> s R p + t, q -> q_R q to a spatial trajectory (quaternions by hand). */
final class RigidMotion {
    private RigidMotion() {
    }

    static SpatialTrajectory apply(SpatialTrajectory a, double[] q, double[] t, double s) {
        int n = a.size();
        double norm = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        double w = q[0] / norm;
        double x = q[1] / norm;
        double y = q[2] / norm;
        double z = q[3] / norm;
        double[][] r = {
            {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
        double[] px = new double[n];
        double[] py = new double[n];
        double[] pz = new double[n];
        double[] qw = new double[n];
        double[] qx = new double[n];
        double[] qy = new double[n];
        double[] qz = new double[n];
        for (int i = 0; i < n; i++) {
            double[] p = {s * a.x(i), s * a.y(i), s * a.z(i)};
            px[i] = r[0][0] * p[0] + r[0][1] * p[1] + r[0][2] * p[2] + t[0];
            py[i] = r[1][0] * p[0] + r[1][1] * p[1] + r[1][2] * p[2] + t[1];
            pz[i] = r[2][0] * p[0] + r[2][1] * p[1] + r[2][2] * p[2] + t[2];
            double bw = a.qw(i);
            double bx = a.qx(i);
            double by = a.qy(i);
            double bz = a.qz(i);
            // Hamilton product q * b
            qw[i] = w * bw - x * bx - y * by - z * bz;
            qx[i] = w * bx + x * bw + y * bz - z * by;
            qy[i] = w * by - x * bz + y * bw + z * bx;
            qz[i] = w * bz + x * by - y * bx + z * bw;
        }
        return SpatialTrajectory.of(a.timestamps(), px, py, pz, qw, qx, qy, qz);
    }
}
