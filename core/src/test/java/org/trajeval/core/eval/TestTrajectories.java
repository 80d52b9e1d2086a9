package org.trajeval.core.eval;

import java.util.Random;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.property.RandomTrajectories;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/** Small trajectories built in tests. */
final class TestTrajectories {
    private TestTrajectories() {
    }

    static LoadedTrajectory loaded(String name, Trajectory t) {
        return RandomTrajectories.loaded(name, t);
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
        return RandomTrajectories.moved(a, theta, tx, ty);
    }

    /** A 3D helix with a varying orientation (no noise). */
    static SpatialTrajectory helix(int n, double dt) {
        return RandomTrajectories.helix(new Random(0), n, dt, 3, 2, 0.3, 0.2, 0.0);
    }
}
