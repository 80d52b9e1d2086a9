package org.trajeval.core.traj;

import java.util.Arrays;
import org.trajeval.core.geom.Rotations;

/**
 * Planar SE(2) trajectory: timestamps t (s), positions x, y (m) and heading yaw (rad, counter-
 * clockwise from +x, any real value; not necessarily wrapped). Immutable: the arrays handed to
 * {@link #of} are owned by the trajectory afterwards and never exposed.
 */
public final class PlanarTrajectory implements Trajectory {
    private final double[] t;
    private final double[] x;
    private final double[] y;
    private final double[] yaw;
    private final int n;

    private PlanarTrajectory(int n, double[] t, double[] x, double[] y, double[] yaw) {
        this.n = n;
        this.t = t;
        this.x = x;
        this.y = y;
        this.yaw = yaw;
    }

    /**
     * Takes ownership of the arrays (the caller must not modify them afterwards).
     *
     * @throws IllegalArgumentException on different lengths, non-finite values or timestamps
     *     that do not increase strictly
     */
    public static PlanarTrajectory of(double[] t, double[] x, double[] y, double[] yaw) {
        TimestampCheck.requireSameLength(t.length, x, y, yaw);
        return ofFirst(t.length, t, x, y, yaw);
    }

    /**
     * The first {@code n} values of the arrays as a trajectory, without copying (readers hand over
     * columns with a little spare capacity). Takes ownership of the arrays.
     *
     * @throws IllegalArgumentException when an array is shorter than n, on non-finite values or
     *     decreasing timestamps
     */
    public static PlanarTrajectory ofFirst(int n, double[] t, double[] x, double[] y, double[] yaw) {
        if (n < 0 || t.length < n || x.length < n || y.length < n || yaw.length < n) {
            throw new IllegalArgumentException("every column needs at least " + n + " values");
        }
        TimestampCheck.requireNonDecreasing(t, n);
        TimestampCheck.requireFinite("x", x, n);
        TimestampCheck.requireFinite("y", y, n);
        TimestampCheck.requireFinite("yaw", yaw, n);
        return new PlanarTrajectory(n, t, x, y, yaw);
    }

    @Override
    public int size() {
        return n;
    }

    @Override
    public double t(int i) {
        return t[i];
    }

    @Override
    public double x(int i) {
        return x[i];
    }

    @Override
    public double y(int i) {
        return y[i];
    }

    @Override
    public double z(int i) {
        return 0.0;
    }

    /** @return heading of pose {@code i} (rad) */
    public double yaw(int i) {
        return yaw[i];
    }

    @Override
    public double[] timestamps() {
        return Arrays.copyOf(t, n);
    }

    /** @return copies of the columns x (m), y (m), yaw (rad) */
    public double[] xs() {
        return Arrays.copyOf(x, n);
    }

    /** @return a copy of y (m) */
    public double[] ys() {
        return Arrays.copyOf(y, n);
    }

    /** @return a copy of yaw (rad) */
    public double[] yaws() {
        return Arrays.copyOf(yaw, n);
    }

    /**
     * Hands the x, y and yaw columns themselves (each at least {@link #size()} long, possibly longer)
     * to a caller that owns this trajectory and reads none of its positions and yaws again: the
     * caller may overwrite them, after which only the stamps and the size of this trajectory hold.
     *
     * @return {x, y, yaw}, not copies
     */
    public double[][] handOverColumns() {
        return new double[][] {x, y, yaw};
    }

    /** @return true when this trajectory and {@code other} hold one of their columns in the same array */
    public boolean sharesColumnsWith(PlanarTrajectory other) {
        double[][] a = {t, x, y, yaw};
        double[][] b = {other.t, other.x, other.y, other.yaw};
        for (double[] u : a) {
            for (double[] v : b) {
                if (u == v) {
                    return true;
                }
            }
        }
        return false;
    }

    @Override
    public void rotation(int i, double[] out, int o) {
        Rotations.aboutZ(yaw[i], out, o);
    }

    @Override
    public SpatialTrajectory toSpatial() {
        int n = size();
        double[] r = new double[9 * n];
        double[] qw = new double[n];
        double[] qz = new double[n];
        for (int i = 0; i < n; i++) {
            Rotations.aboutZ(yaw[i], r, 9 * i);
            qw[i] = Math.cos(0.5 * yaw[i]);
            qz[i] = Math.sin(0.5 * yaw[i]);
        }
        return SpatialTrajectory.ofPoses(Arrays.copyOf(t, n), PoseSequence.of(Arrays.copyOf(x, n),
                Arrays.copyOf(y, n), new double[n], r), new double[][] {qw, new double[n], new double[n], qz});
    }

    @Override
    public PlanarTrajectory toPlanar() {
        return this;
    }

    @Override
    public PlanarTrajectory slice(int from, int to) {
        return new PlanarTrajectory(to - from, Arrays.copyOfRange(t, from, to), Arrays.copyOfRange(x, from, to),
                Arrays.copyOfRange(y, from, to), Arrays.copyOfRange(yaw, from, to));
    }
}
