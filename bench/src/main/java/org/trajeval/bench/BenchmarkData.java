package org.trajeval.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Random;
import org.trajeval.core.io.TrajectoryWriter;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Seeded benchmark pairs, as bench/python/generate.py makes them: a 100 Hz reference on a smooth
 * path, and an estimate on stamps 3 ms later (so association interpolates) with drift, noise and
 * a rigid offset. Planar: x, y (m), yaw (rad); spatial: the same path with z, pitch and roll.
 */
final class BenchmarkData {
    private BenchmarkData() {
    }

    /** @return {reference, estimate} of n poses each */
    static PlanarTrajectory[] planarPair(int n, long seed) {
        Random rnd = new Random(seed);
        PlanarTrajectory[] pair = new PlanarTrajectory[2];
        for (int k = 0; k < 2; k++) {
            double[] t = new double[n];
            double[] x = new double[n];
            double[] y = new double[n];
            double[] yaw = new double[n];
            double c = Math.cos(0.3 * k);
            double sn = Math.sin(0.3 * k);
            for (int i = 0; i < n; i++) {
                double s = i * 0.01 + 0.003 * k;
                double px = 0.5 * s + 2 * Math.sin(0.15 * s) + 40 * Math.sin(s / 300);
                double py = 1.5 * Math.cos(0.1 * s) + 30 * Math.cos(s / 500);
                double h = Math.atan2(-0.15 * Math.sin(0.1 * s) - 0.06 * Math.sin(s / 500),
                        0.5 + 0.3 * Math.cos(0.15 * s) + (40.0 / 300) * Math.cos(s / 300));
                if (k == 1) {
                    px += 1e-4 * s + 0.02 * rnd.nextGaussian();
                    py += -5e-5 * s + 0.02 * rnd.nextGaussian();
                    h += 0.005 * rnd.nextGaussian();
                }
                t[i] = 1000 + s;
                x[i] = c * px - sn * py + 5 * k;
                y[i] = sn * px + c * py - 2 * k;
                yaw[i] = h + 0.3 * k;
            }
            pair[k] = PlanarTrajectory.of(t, x, y, yaw);
        }
        return pair;
    }

    /** @return {reference, estimate} of n poses each, spatial (z, pitch and roll wobble) */
    static SpatialTrajectory[] spatialPair(int n, long seed) {
        PlanarTrajectory[] p = planarPair(n, seed);
        SpatialTrajectory[] out = new SpatialTrajectory[2];
        for (int k = 0; k < 2; k++) {
            PlanarTrajectory a = p[k];
            double[] z = new double[n];
            double[] qw = new double[n];
            double[] qx = new double[n];
            double[] qy = new double[n];
            double[] qz = new double[n];
            for (int i = 0; i < n; i++) {
                double s = a.t(i) - 1000;
                z[i] = 0.2 * Math.sin(s / 50);
                double yaw = a.yaw(i);
                double pitch = 0.05 * Math.sin(s / 13);
                double roll = 0.04 * Math.cos(s / 17);
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
            out[k] = SpatialTrajectory.of(a.timestamps().clone(), a.xs().clone(), a.ys().clone(), z, qw, qx, qy, qz);
        }
        return out;
    }

    /** Writes the trajectory to a temporary file with the given suffix (.csv planar, .txt TUM). */
    static Path write(Object trajectory, String suffix) {
        try {
            Path p = Files.createTempFile("trajeval-jmh", suffix);
            p.toFile().deleteOnExit();
            TrajectoryWriter.write((org.trajeval.core.traj.Trajectory) trajectory, p);
            return p;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
