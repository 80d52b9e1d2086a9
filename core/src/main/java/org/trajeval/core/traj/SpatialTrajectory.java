package org.trajeval.core.traj;

import java.util.Arrays;
import org.trajeval.core.geom.Rotations;

/**
 * Full SE(3) trajectory: timestamps t (s), positions x, y, z (m) and orientations as rotation
 * matrices R that map body-frame vectors into the world frame: {@code p_world = R p_body + t}.
 * Built from unit quaternions (w, x, y, z; Hamilton) or directly from matrices (KITTI). Worked
 * example: a rotation of +90 deg about +z is q = (cos 45 deg, 0, 0, sin 45 deg) and maps the
 * body x axis to world +y. See {@link Rotations} for the storage layout.
 *
 * <p>Immutable: the arrays handed to the factories are owned by the trajectory afterwards.
 * Memory: built from quaternions, a pose takes 64 B (t, x, y, z and the quaternion's four
 * columns, kept as handed over: no copy); the rotation matrices (72 B per pose) are derived on
 * demand ({@link #rotation}) and materialised only when {@link #poses()} is asked for (the
 * general path, plots), once.
 */
public final class SpatialTrajectory implements Trajectory {
    private final int n;
    private final double[] t;
    private final double[] px;
    private final double[] py;
    private final double[] pz;
    private final double[] qw;
    private final double[] qx;
    private final double[] qy;
    private final double[] qz;
    private volatile PoseSequence poses;

    private SpatialTrajectory(int n, double[] t, double[] x, double[] y, double[] z, double[][] q,
            PoseSequence poses) {
        this.n = n;
        this.t = t;
        this.px = x;
        this.py = y;
        this.pz = z;
        this.qw = q == null ? null : q[0];
        this.qx = q == null ? null : q[1];
        this.qy = q == null ? null : q[2];
        this.qz = q == null ? null : q[3];
        this.poses = poses;
    }

    /**
     * From quaternions (w, x, y, z), kept exactly as given (readers check their norm; evo also
     * keeps them and normalises inside its conversions, as {@link Rotations#fromQuaternion} and
     * {@link Rotations#slerp} do).
     *
     * @throws IllegalArgumentException on different lengths, non-finite values, a zero
     *     quaternion or decreasing timestamps
     */
    public static SpatialTrajectory of(double[] t, double[] x, double[] y, double[] z,
            double[] qw, double[] qx, double[] qy, double[] qz) {
        TimestampCheck.requireSameLength(t.length, x, y, z, qw, qx, qy, qz);
        return ofFirst(t.length, t, x, y, z, qw, qx, qy, qz);
    }

    /**
     * The first {@code n} values of the columns as a trajectory, without copying (readers hand
     * over columns with a little spare capacity). Takes ownership of the arrays.
     *
     * @throws IllegalArgumentException when a column is shorter than n, on non-finite values, a
     *     zero quaternion or decreasing timestamps
     */
    public static SpatialTrajectory ofFirst(int n, double[] t, double[] x, double[] y, double[] z,
            double[] qw, double[] qx, double[] qy, double[] qz) {
        for (double[] c : new double[][] {t, x, y, z, qw, qx, qy, qz}) {
            if (n < 0 || c.length < n) {
                throw new IllegalArgumentException("every column needs at least " + n + " values");
            }
        }
        if (!allValid(n, t, x, y, z, qw, qx, qy, qz)) {
            TimestampCheck.requireNonDecreasing(t, n);
            for (double[] c : new double[][] {x, y, z, qw, qx, qy, qz}) {
                TimestampCheck.requireFinite("pose", c, n);
            }
            for (int i = 0; i < n; i++) {
                if (!(quaternionNorm(qw[i], qx[i], qy[i], qz[i]) > 0.0)) {
                    throw new IllegalArgumentException("quaternion " + i + " is zero");
                }
            }
        }
        return new SpatialTrajectory(n, t, x, y, z, new double[][] {qw, qx, qy, qz}, null);
    }

    /**
     * The checks of {@link #ofFirst} in one pass over the poses, without saying which failed
     * (the checks are then run one by one, in their order, for the refusal): finite timestamps
     * that do not decrease, finite values ({@code v * 0.0} is 0 exactly when v is finite) and a
     * quaternion norm above 0 (its square: no square root).
     *
     * @return true when every check passes
     */
    private static boolean allValid(int n, double[] t, double[] x, double[] y, double[] z,
            double[] qw, double[] qx, double[] qy, double[] qz) {
        boolean valid = true;
        double before = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            double ti = t[i];
            double zeros = x[i] * 0.0 + y[i] * 0.0 + z[i] * 0.0 + qw[i] * 0.0 + qx[i] * 0.0 + qy[i] * 0.0 + qz[i] * 0.0;
            // sqrt(s) > 0 exactly when s > 0 (s = 0, NaN: both false; s = +inf: both true)
            valid &= Double.isFinite(ti) & ti >= before & zeros == 0.0
                    & qw[i] * qw[i] + qx[i] * qx[i] + qy[i] * qy[i] + qz[i] * qz[i] > 0.0;
            before = ti;
        }
        return valid;
    }

    /** @return the norm of the quaternion (w, x, y, z) */
    private static double quaternionNorm(double w, double x, double y, double z) {
        return Math.sqrt(w * w + x * x + y * y + z * z);
    }

    /**
     * From rotation matrices (9 per pose, row-major), kept exactly as given (KITTI files are
     * orthonormal only to about 1e-6; evo keeps them as read, so do we).
     */
    public static SpatialTrajectory ofMatrices(double[] t, double[] x, double[] y, double[] z, double[] r) {
        TimestampCheck.requireSameLength(t.length, x, y, z);
        TimestampCheck.requireNonDecreasing(t);
        TimestampCheck.requireFinite("x", x);
        TimestampCheck.requireFinite("y", y);
        TimestampCheck.requireFinite("z", z);
        TimestampCheck.requireFinite("rotation", r);
        return new SpatialTrajectory(t.length, t, x, y, z, null, PoseSequence.of(x, y, z, r));
    }

    /** From timestamps, poses and their quaternion columns w, x, y, z (package use: planar lifted to SE(3)). */
    static SpatialTrajectory ofPoses(double[] t, PoseSequence poses, double[][] q) {
        double[][] p = poses.positionColumns();
        return new SpatialTrajectory(t.length, t, p[0], p[1], p[2], q, poses);
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
        return px[i];
    }

    @Override
    public double y(int i) {
        return py[i];
    }

    @Override
    public double z(int i) {
        return pz[i];
    }

    /**
     * The rotation matrix of pose i: as given (matrices), or {@link Rotations#fromQuaternion} of
     * the quaternion as read, bit for bit the matrix {@link #poses()} holds.
     */
    @Override
    public void rotation(int i, double[] out, int o) {
        PoseSequence p = poses;
        if (p != null) {
            p.rotation(i, out, o);
        } else {
            Rotations.fromQuaternion(qw[i], qx[i], qy[i], qz[i], out, o);
        }
    }

    /** @return the poses without their timestamps (rotation matrices materialised on first call) */
    public PoseSequence poses() {
        PoseSequence p = poses;
        if (p == null) {
            synchronized (this) {
                p = poses;
                if (p == null) {
                    double[] r = new double[9 * n];
                    for (int i = 0; i < n; i++) {
                        rotation(i, r, 9 * i);
                    }
                    p = PoseSequence.of(exact(px), exact(py), exact(pz), r);
                    poses = p;
                }
            }
        }
        return p;
    }

    private double[] exact(double[] column) {
        return column.length == n ? column : Arrays.copyOf(column, n);
    }

    /**
     * Quaternion (w, x, y, z) of pose i as read (not re-derived from the matrix) when the
     * trajectory was built from quaternions; otherwise derived from the matrix with w >= 0.
     *
     * @param out receives w, x, y, z
     */
    public void quaternion(int i, double[] out) {
        if (qw != null) {
            out[0] = qw[i];
            out[1] = qx[i];
            out[2] = qy[i];
            out[3] = qz[i];
        } else {
            double[] r = new double[9];
            poses.rotation(i, r, 0);
            Rotations.toQuaternion(r, 0, out);
        }
    }

    /** @return quaternion scalar part w of pose i (as read, or derived from the matrix) */
    public double qw(int i) {
        return qw != null ? qw[i] : quaternionPart(i, 0);
    }

    /** @return quaternion x part of pose i */
    public double qx(int i) {
        return qx != null ? qx[i] : quaternionPart(i, 1);
    }

    /** @return quaternion y part of pose i */
    public double qy(int i) {
        return qy != null ? qy[i] : quaternionPart(i, 2);
    }

    /** @return quaternion z part of pose i */
    public double qz(int i) {
        return qz != null ? qz[i] : quaternionPart(i, 3);
    }

    private double quaternionPart(int i, int k) {
        double[] out = new double[4];
        quaternion(i, out);
        return out[k];
    }

    @Override
    public double[] timestamps() {
        return Arrays.copyOf(t, n);
    }

    @Override
    public SpatialTrajectory toSpatial() {
        return this;
    }

    @Override
    public PlanarTrajectory toPlanar() {
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        double[] r = new double[9];
        for (int i = 0; i < n; i++) {
            x[i] = px[i];
            y[i] = py[i];
            rotation(i, r, 0);
            yaw[i] = Rotations.yaw(r, 0);
        }
        return PlanarTrajectory.of(Arrays.copyOf(t, n), x, y, yaw);
    }

    @Override
    public SpatialTrajectory slice(int from, int to) {
        if (to > n) {
            throw new IndexOutOfBoundsException("slice [" + from + ", " + to + ") of " + n + " poses");
        }
        double[] nt = Arrays.copyOfRange(t, from, to);
        if (qw == null) {
            return ofPoses(nt, poses.slice(from, to), null);
        }
        return new SpatialTrajectory(to - from, nt, Arrays.copyOfRange(px, from, to), Arrays.copyOfRange(py, from, to),
                Arrays.copyOfRange(pz, from, to), new double[][] {Arrays.copyOfRange(qw, from, to),
                    Arrays.copyOfRange(qx, from, to), Arrays.copyOfRange(qy, from, to), Arrays.copyOfRange(qz, from, to)},
                null);
    }
}
