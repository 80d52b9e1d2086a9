package org.trajeval.core.property;

import java.util.Random;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/** Seeded random smooth trajectories and rigid motions for the property checks. */
public final class RandomTrajectories {
    private RandomTrajectories() {
    }

    public static LoadedTrajectory loaded(String name, Trajectory t) {
        return new LoadedTrajectory(name, t instanceof PlanarTrajectory ? TrajectoryFormat.CSV : TrajectoryFormat.TUM,
                "test", t, "0", false);
    }

    /** A smooth planar path of n poses every dt s: sums of sines with random amplitudes and frequencies; yaw = heading. */
    public static PlanarTrajectory planarPath(Random rnd, int n, double dt) {
        double ax = 1 + 5 * rnd.nextDouble();
        double ay = 1 + 5 * rnd.nextDouble();
        double wx = 0.05 + 0.3 * rnd.nextDouble();
        double wy = 0.05 + 0.3 * rnd.nextDouble();
        double v = 0.2 + rnd.nextDouble();
        double t0 = 100 * rnd.nextDouble();
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        for (int i = 0; i < n; i++) {
            double s = i * dt;
            t[i] = t0 + s;
            x[i] = v * s + ax * Math.sin(wx * s);
            y[i] = ay * Math.cos(wy * s);
            yaw[i] = Math.atan2(-ay * wy * Math.sin(wy * s), v + ax * wx * Math.cos(wx * s));
        }
        return PlanarTrajectory.of(t, x, y, yaw);
    }

    /** The path with seeded Gaussian noise: sigma (m) on x, y and sigma (rad) on yaw. */
    public static PlanarTrajectory noisy(Random rnd, PlanarTrajectory a, double sigma) {
        int n = a.size();
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = a.x(i) + sigma * rnd.nextGaussian();
            y[i] = a.y(i) + sigma * rnd.nextGaussian();
            yaw[i] = a.yaw(i) + sigma * rnd.nextGaussian();
        }
        return PlanarTrajectory.of(a.timestamps().clone(), x, y, yaw);
    }

    /** p -> R(theta) p + (tx, ty), yaw -> yaw + theta, for every pose. */
    public static PlanarTrajectory moved(PlanarTrajectory a, double theta, double tx, double ty) {
        int n = a.size();
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        double c = Math.cos(theta);
        double s = Math.sin(theta);
        for (int i = 0; i < n; i++) {
            x[i] = c * a.x(i) - s * a.y(i) + tx;
            y[i] = s * a.x(i) + c * a.y(i) + ty;
            yaw[i] = a.yaw(i) + theta;
        }
        return PlanarTrajectory.of(a.timestamps().clone(), x, y, yaw);
    }

    /** A random unit quaternion (w, x, y, z), uniform on the sphere. */
    public static double[] randomQuaternion(Random rnd) {
        double[] q = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
        double norm = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        for (int i = 0; i < 4; i++) {
            q[i] /= norm;
        }
        return q;
    }

    /** A 3D path: a helix with random radii and pitch, orientation from a slowly varying yaw-pitch-roll. */
    public static SpatialTrajectory spatialPath(Random rnd, int n, double dt, double noise) {
        double rx = 1 + 4 * rnd.nextDouble();
        double ry = 1 + 4 * rnd.nextDouble();
        double w = 0.1 + 0.4 * rnd.nextDouble();
        double vz = 0.05 + 0.3 * rnd.nextDouble();
        return helix(rnd, n, dt, rx, ry, w, vz, noise);
    }

    /**
     * A helix x = rx cos(w s), y = ry sin(w s), z = vz s with heading w s, pitch 0.2 sin(0.5 s)
     * and roll 0.1 cos(0.7 s) (quaternion from yaw-pitch-roll), plus seeded noise (m, rad).
     */
    public static SpatialTrajectory helix(Random rnd, int n, double dt, double rx, double ry, double w, double vz,
            double noise) {
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] z = new double[n];
        double[] qw = new double[n];
        double[] qx = new double[n];
        double[] qy = new double[n];
        double[] qz = new double[n];
        for (int i = 0; i < n; i++) {
            double s = i * dt;
            t[i] = s;
            x[i] = rx * Math.cos(w * s) + noise * rnd.nextGaussian();
            y[i] = ry * Math.sin(w * s) + noise * rnd.nextGaussian();
            z[i] = vz * s + noise * rnd.nextGaussian();
            double yaw = w * s + noise * rnd.nextGaussian();
            double pitch = 0.2 * Math.sin(0.5 * s);
            double roll = 0.1 * Math.cos(0.7 * s);
            double cy = Math.cos(yaw / 2);
            double sy = Math.sin(yaw / 2);
            double cp = Math.cos(pitch / 2);
            double sp = Math.sin(pitch / 2);
            double cr = Math.cos(roll / 2);
            double sr = Math.sin(roll / 2);
            qw[i] = cr * cp * cy + sr * sp * sy;
            qx[i] = sr * cp * cy - cr * sp * sy;
            qy[i] = cr * sp * cy + sr * cp * sy;
            qz[i] = cr * cp * sy - sr * sp * cy;
        }
        return SpatialTrajectory.of(t, x, y, z, qw, qx, qy, qz);
    }

    /** Rotation matrix (row-major 3x3) of a unit quaternion (w, x, y, z). */
    public static double[][] matrix(double[] q) {
        double w = q[0];
        double x = q[1];
        double y = q[2];
        double z = q[3];
        return new double[][] {
            {1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    }

    /** p -> s R(q) p + t, q_i -> q q_i (Hamilton product) for every pose. */
    public static SpatialTrajectory moved(SpatialTrajectory a, double[] q, double[] t, double s) {
        int n = a.size();
        double[][] r = matrix(q);
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
            qw[i] = q[0] * bw - q[1] * bx - q[2] * by - q[3] * bz;
            qx[i] = q[0] * bx + q[1] * bw + q[2] * bz - q[3] * by;
            qy[i] = q[0] * by - q[1] * bz + q[2] * bw + q[3] * bx;
            qz[i] = q[0] * bz + q[1] * by - q[2] * bx + q[3] * bw;
        }
        return SpatialTrajectory.of(a.timestamps().clone(), px, py, pz, qw, qx, qy, qz);
    }
}
