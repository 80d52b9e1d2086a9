package org.trajeval.core.eval;

import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/** Small trajectories built in tests. */
final class TestTrajectories {
    private TestTrajectories() {
    }

    static LoadedTrajectory loaded(String name, Trajectory t) {
        return new LoadedTrajectory(name, t instanceof PlanarTrajectory ? TrajectoryFormat.CSV : TrajectoryFormat.TUM,
                "test", t, "0", false);
    }

    /** A smooth planar path like the lesson's demo: x = 0.5 t + 2 sin 0.15 t, y = 1.5 cos 0.1 t, yaw = heading. */
    static PlanarTrajectory lessonPath(int n, double dt) {
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        for (int i = 0; i < n; i++) {
            double s = i * dt;
            t[i] = s;
            x[i] = 0.5 * s + 2.0 * Math.sin(0.15 * s);
            y[i] = 1.5 * Math.cos(0.10 * s);
            yaw[i] = Math.atan2(-0.15 * Math.sin(0.10 * s), 0.5 + 0.3 * Math.cos(0.15 * s));
        }
        return PlanarTrajectory.of(t, x, y, yaw);
    }

    /** Applies p -> R(theta) p + (tx, ty), yaw -> yaw + theta to every pose. */
    static PlanarTrajectory moved(PlanarTrajectory a, double theta, double tx, double ty) {
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
        return PlanarTrajectory.of(a.timestamps(), x, y, yaw);
    }

    /** A 3D helix with a varying orientation (quaternions from a yaw-pitch-roll that changes with time). */
    static SpatialTrajectory helix(int n, double dt) {
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
            x[i] = 3 * Math.cos(0.3 * s);
            y[i] = 2 * Math.sin(0.3 * s);
            z[i] = 0.2 * s;
            double yaw = 0.3 * s;
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
}
