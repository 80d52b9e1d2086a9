package org.trajeval.core.traj;

import org.trajeval.core.geom.Rotations;

/**
 * Full SE(3) trajectory: timestamps t (s), positions x, y, z (m) and orientations as rotation
 * matrices R that map body-frame vectors into the world frame: {@code p_world = R p_body + t}.
 * Built from unit quaternions (w, x, y, z; Hamilton) or directly from matrices (KITTI). Worked
 * example: a rotation of +90 deg about +z is q = (cos 45 deg, 0, 0, sin 45 deg) and maps the
 * body x axis to world +y. See {@link Rotations} for the storage layout.
 *
 * <p>Immutable: the arrays handed to the factories are owned by the trajectory afterwards.
 * Memory: built from quaternions, a pose takes 64 B (t, x, y, z, w, qx, qy, qz); the rotation
 * matrices (72 B per pose) are derived on demand ({@link #rotation}) and only materialised when
 * {@link #poses()} is asked for (the general path, plots), once.
 */
public final class SpatialTrajectory implements Trajectory {
    private final double[] t;
    private final double[] px;
    private final double[] py;
    private final double[] pz;
    private final double[] q;
    private volatile PoseSequence poses;

    private SpatialTrajectory(double[] t, PoseSequence poses, double[] q) {
        this.t = t;
        this.poses = poses;
        double[][] p = poses.positionColumns();
        this.px = p[0];
        this.py = p[1];
        this.pz = p[2];
        this.q = q;
    }

    private SpatialTrajectory(double[] t, double[] x, double[] y, double[] z, double[] q) {
        this.t = t;
        this.px = x;
        this.py = y;
        this.pz = z;
        this.q = q;
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
        TimestampCheck.requireNonDecreasing(t);
        for (double[] c : new double[][] {x, y, z, qw, qx, qy, qz}) {
            TimestampCheck.requireFinite("pose", c);
        }
        int n = t.length;
        double[] q = new double[4 * n];
        for (int i = 0; i < n; i++) {
            double norm = Math.sqrt(qw[i] * qw[i] + qx[i] * qx[i] + qy[i] * qy[i] + qz[i] * qz[i]);
            if (!(norm > 0.0)) {
                throw new IllegalArgumentException("quaternion " + i + " is zero");
            }
            q[4 * i] = qw[i];
            q[4 * i + 1] = qx[i];
            q[4 * i + 2] = qy[i];
            q[4 * i + 3] = qz[i];
        }
        return new SpatialTrajectory(t, x, y, z, q);
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
        return new SpatialTrajectory(t, PoseSequence.of(x, y, z, r), null);
    }

    /** From timestamps and poses (package use: interpolation, transforms). */
    static SpatialTrajectory ofPoses(double[] t, PoseSequence poses, double[] q) {
        return new SpatialTrajectory(t, poses, q);
    }

    @Override
    public int size() {
        return t.length;
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
            Rotations.fromQuaternion(q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3], out, o);
        }
    }

    /** @return the poses without their timestamps (rotation matrices materialised on first call) */
    public PoseSequence poses() {
        PoseSequence p = poses;
        if (p == null) {
            synchronized (this) {
                p = poses;
                if (p == null) {
                    int n = t.length;
                    double[] r = new double[9 * n];
                    for (int i = 0; i < n; i++) {
                        Rotations.fromQuaternion(q[4 * i], q[4 * i + 1], q[4 * i + 2], q[4 * i + 3], r, 9 * i);
                    }
                    p = PoseSequence.of(px, py, pz, r);
                    poses = p;
                }
            }
        }
        return p;
    }

    /**
     * Quaternion (w, x, y, z) of pose i as read (not re-derived from the matrix) when the
     * trajectory was built from quaternions; otherwise derived from the matrix with w >= 0.
     *
     * @param out receives w, x, y, z
     */
    public void quaternion(int i, double[] out) {
        if (q != null) {
            System.arraycopy(q, 4 * i, out, 0, 4);
        } else {
            double[] r = new double[9];
            poses().rotation(i, r, 0);
            Rotations.toQuaternion(r, 0, out);
        }
    }

    /** @return quaternion scalar part w of pose i (as read, or derived from the matrix) */
    public double qw(int i) {
        return quaternionPart(i, 0);
    }

    /** @return quaternion x part of pose i */
    public double qx(int i) {
        return quaternionPart(i, 1);
    }

    /** @return quaternion y part of pose i */
    public double qy(int i) {
        return quaternionPart(i, 2);
    }

    /** @return quaternion z part of pose i */
    public double qz(int i) {
        return quaternionPart(i, 3);
    }

    private double quaternionPart(int i, int k) {
        if (q != null) {
            return q[4 * i + k];
        }
        double[] out = new double[4];
        quaternion(i, out);
        return out[k];
    }

    @Override
    public double[] timestamps() {
        return t.clone();
    }

    @Override
    public SpatialTrajectory toSpatial() {
        return this;
    }

    @Override
    public PlanarTrajectory toPlanar() {
        int n = size();
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
        return PlanarTrajectory.of(t.clone(), x, y, yaw);
    }

    @Override
    public SpatialTrajectory slice(int from, int to) {
        double[] nt = java.util.Arrays.copyOfRange(t, from, to);
        if (q == null) {
            return new SpatialTrajectory(nt, poses.slice(from, to), null);
        }
        return new SpatialTrajectory(nt, java.util.Arrays.copyOfRange(px, from, to),
                java.util.Arrays.copyOfRange(py, from, to), java.util.Arrays.copyOfRange(pz, from, to),
                java.util.Arrays.copyOfRange(q, 4 * from, 4 * to));
    }
}
