package org.trajeval.core.traj;

import java.util.Arrays;
import org.trajeval.core.geom.Rotations;

/**
 * An ordered list of SE(3) poses without time-order requirements (e.g. the reference poses
 * associated to an estimate, where one reference pose may appear twice). Column-wise storage:
 * positions x, y, z (m) and rotation matrices (9 doubles per pose, row-major; see
 * {@link Rotations} for the conventions). Immutable: arrays passed to {@link #of} are owned.
 */
public final class PoseSequence implements PositionColumns {
    private final double[] x;
    private final double[] y;
    private final double[] z;
    private final double[] r;

    private PoseSequence(double[] x, double[] y, double[] z, double[] r) {
        this.x = x;
        this.y = y;
        this.z = z;
        this.r = r;
    }

    /**
     * Takes ownership of the arrays.
     *
     * @param r rotation matrices, 9 per pose, row-major
     * @throws IllegalArgumentException on inconsistent lengths
     */
    public static PoseSequence of(double[] x, double[] y, double[] z, double[] r) {
        if (y.length != x.length || z.length != x.length || r.length != 9L * x.length) {
            throw new IllegalArgumentException("pose columns have inconsistent lengths");
        }
        return new PoseSequence(x, y, z, r);
    }

    /** @return number of poses */
    public int size() {
        return x.length;
    }

    /** @return x of pose i (m) */
    @Override
    public double x(int i) {
        return x[i];
    }

    /** @return y of pose i (m) */
    @Override
    public double y(int i) {
        return y[i];
    }

    /** @return z of pose i (m) */
    @Override
    public double z(int i) {
        return z[i];
    }

    /** @return element (row, col) of the rotation of pose i */
    public double r(int i, int row, int col) {
        return r[9 * i + 3 * row + col];
    }

    /** Copies the rotation matrix of pose i into {@code out[o..o+9)}. */
    public void rotation(int i, double[] out, int o) {
        System.arraycopy(r, 9 * i, out, o, 9);
    }

    /** @return a copy of all rotation matrices (9 per pose, row-major) */
    public double[] rotations() {
        return r.clone();
    }

    /** @return x, y, z themselves (package use: trajectories sharing the immutable columns) */
    double[][] positionColumns() {
        return new double[][] {x, y, z};
    }

    /** @return copies of x, y, z */
    public double[][] positions() {
        return new double[][] {x.clone(), y.clone(), z.clone()};
    }

    /** @return the poses with the given indices, in that order (indices may repeat) */
    public PoseSequence select(int[] indices, int count) {
        double[] nx = new double[count];
        double[] ny = new double[count];
        double[] nz = new double[count];
        double[] nr = new double[9 * count];
        for (int k = 0; k < count; k++) {
            int i = indices[k];
            nx[k] = x[i];
            ny[k] = y[i];
            nz[k] = z[i];
            System.arraycopy(r, 9 * i, nr, 9 * k, 9);
        }
        return new PoseSequence(nx, ny, nz, nr);
    }

    /** @return the poses [from, to) */
    public PoseSequence slice(int from, int to) {
        return new PoseSequence(Arrays.copyOfRange(x, from, to), Arrays.copyOfRange(y, from, to),
                Arrays.copyOfRange(z, from, to), Arrays.copyOfRange(r, 9 * from, 9 * to));
    }
}
