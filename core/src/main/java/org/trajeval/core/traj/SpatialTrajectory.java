package org.trajeval.core.traj;

import java.util.Arrays;

/**
 * Full SE(3) trajectory: timestamps t (s), positions x, y, z (m) and orientations as unit
 * quaternions (qw, qx, qy, qz), Hamilton convention, rotating body-frame vectors into the world
 * frame: {@code p_world = R(q) p_body + t}. Worked example: a rotation of +90 deg about +z is
 * q = (cos 45 deg, 0, 0, sin 45 deg) and maps the body x axis to world +y.
 *
 * <p>Immutable: the arrays handed to {@link #of} are owned by the trajectory afterwards.
 */
public final class SpatialTrajectory implements Trajectory {
    /** Rounding error of the norm of a quaternion normalised in double precision: 4 ulp(1). */
    private static final double UNIT_NORM_ROUNDING = 4 * Math.ulp(1.0);

    private final double[] t;
    private final double[] x;
    private final double[] y;
    private final double[] z;
    private final double[] qw;
    private final double[] qx;
    private final double[] qy;
    private final double[] qz;

    private SpatialTrajectory(double[] t, double[] x, double[] y, double[] z,
            double[] qw, double[] qx, double[] qy, double[] qz) {
        this.t = t;
        this.x = x;
        this.y = y;
        this.z = z;
        this.qw = qw;
        this.qx = qx;
        this.qy = qy;
        this.qz = qz;
    }

    /**
     * Takes ownership of the arrays. Quaternions are used as given (readers check and report
     * their norm; see {@code QuaternionCheck}); they are normalised here so that every rotation
     * is exact.
     *
     * @throws IllegalArgumentException on different lengths, non-finite values, a zero
     *     quaternion or timestamps that do not increase strictly
     */
    public static SpatialTrajectory of(double[] t, double[] x, double[] y, double[] z,
            double[] qw, double[] qx, double[] qy, double[] qz) {
        TimestampCheck.requireSameLength(t.length, x, y, z, qw, qx, qy, qz);
        TimestampCheck.requireStrictlyIncreasing(t);
        for (double[] c : new double[][] {x, y, z, qw, qx, qy, qz}) {
            TimestampCheck.requireFinite("pose", c);
        }
        for (int i = 0; i < t.length; i++) {
            double norm = Math.sqrt(qw[i] * qw[i] + qx[i] * qx[i] + qy[i] * qy[i] + qz[i] * qz[i]);
            if (!(norm > 0.0)) {
                throw new IllegalArgumentException("quaternion " + i + " is zero");
            }
            // a quaternion already normalised (|norm - 1| within rounding) is kept bit for bit, so
            // that normalising is idempotent and written trajectories read back exactly
            if (Math.abs(norm - 1.0) > UNIT_NORM_ROUNDING) {
                qw[i] /= norm;
                qx[i] /= norm;
                qy[i] /= norm;
                qz[i] /= norm;
            }
        }
        return new SpatialTrajectory(t, x, y, z, qw, qx, qy, qz);
    }

    /** For arrays already checked (same length, increasing t, unit quaternions). */
    static SpatialTrajectory ofTrusted(double[] t, double[] x, double[] y, double[] z,
            double[] qw, double[] qx, double[] qy, double[] qz) {
        return new SpatialTrajectory(t, x, y, z, qw, qx, qy, qz);
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
        return x[i];
    }

    @Override
    public double y(int i) {
        return y[i];
    }

    @Override
    public double z(int i) {
        return z[i];
    }

    /** @return quaternion scalar part of pose {@code i} */
    public double qw(int i) {
        return qw[i];
    }

    /** @return quaternion x part of pose {@code i} */
    public double qx(int i) {
        return qx[i];
    }

    /** @return quaternion y part of pose {@code i} */
    public double qy(int i) {
        return qy[i];
    }

    /** @return quaternion z part of pose {@code i} */
    public double qz(int i) {
        return qz[i];
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
        double[] yaw = new double[n];
        for (int i = 0; i < n; i++) {
            // R00 = 1 - 2(qy^2 + qz^2), R10 = 2(qx qy + qw qz)
            double r00 = 1.0 - 2.0 * (qy[i] * qy[i] + qz[i] * qz[i]);
            double r10 = 2.0 * (qx[i] * qy[i] + qw[i] * qz[i]);
            yaw[i] = Math.atan2(r10, r00);
        }
        return PlanarTrajectory.of(t.clone(), x.clone(), y.clone(), yaw);
    }

    @Override
    public SpatialTrajectory slice(int from, int to) {
        return new SpatialTrajectory(Arrays.copyOfRange(t, from, to), Arrays.copyOfRange(x, from, to),
                Arrays.copyOfRange(y, from, to), Arrays.copyOfRange(z, from, to),
                Arrays.copyOfRange(qw, from, to), Arrays.copyOfRange(qx, from, to),
                Arrays.copyOfRange(qy, from, to), Arrays.copyOfRange(qz, from, to));
    }
}
