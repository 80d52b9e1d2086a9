package org.trajeval.core.geom;

/**
 * Rotation matrices stored as 9 doubles, row-major, at an offset of an array:
 * {@code r[o + 3*row + col]}. Conventions (Hamilton quaternions, active rotations):
 * a rotation of +90 deg about +z is q = (w, x, y, z) = (cos 45 deg, 0, 0, sin 45 deg) and has the
 * matrix rows (0, -1, 0), (1, 0, 0), (0, 0, 1): it maps the body x axis to world +y.
 */
public final class Rotations {
    /** Four machine epsilons, the threshold of the transformations.py conventions evo uses. */
    private static final double EPS4 = 4.0 * Math.ulp(1.0);

    private Rotations() {
    }

    /**
     * Writes the rotation matrix of quaternion (w, x, y, z) into {@code r[o..o+9)}. The quaternion
     * need not be unit: it is scaled by sqrt(2 / |q|^2) first, exactly as evo (transformations.py
     * {@code quaternion_matrix}) does, so both tools start from bit-identical matrices.
     */
    public static void fromQuaternion(double w, double x, double y, double z, double[] r, int o) {
        double n = w * w + x * x + y * y + z * z;
        if (n < EPS4) {
            identity(r, o);
            return;
        }
        double s = Math.sqrt(2.0 / n);
        w *= s;
        x *= s;
        y *= s;
        z *= s;
        // outer product terms q[i]*q[j] with q = (w, x, y, z)
        double xx = x * x;
        double yy = y * y;
        double zz = z * z;
        double xy = x * y;
        double xz = x * z;
        double yz = y * z;
        double wx = x * w;
        double wy = y * w;
        double wz = z * w;
        r[o] = 1.0 - yy - zz;
        r[o + 1] = xy - wz;
        r[o + 2] = xz + wy;
        r[o + 3] = xy + wz;
        r[o + 4] = 1.0 - xx - zz;
        r[o + 5] = yz - wx;
        r[o + 6] = xz - wy;
        r[o + 7] = yz + wx;
        r[o + 8] = 1.0 - xx - yy;
    }

    /** Writes the identity into {@code r[o..o+9)}. */
    public static void identity(double[] r, int o) {
        for (int k = 0; k < 9; k++) {
            r[o + k] = (k % 4 == 0) ? 1.0 : 0.0;
        }
    }

    /** Writes a rotation about +z by {@code yaw} (rad) into {@code r[o..o+9)}. */
    public static void aboutZ(double yaw, double[] r, int o) {
        double c = Math.cos(yaw);
        double s = Math.sin(yaw);
        r[o] = c;
        r[o + 1] = -s;
        r[o + 2] = 0.0;
        r[o + 3] = s;
        r[o + 4] = c;
        r[o + 5] = 0.0;
        r[o + 6] = 0.0;
        r[o + 7] = 0.0;
        r[o + 8] = 1.0;
    }

    /**
     * Unit quaternion (w, x, y, z) with w >= 0 of the rotation matrix at {@code r[o]}
     * (Shepperd's method: the largest of trace, r00, r11, r22 decides the branch).
     *
     * @param q receives w, x, y, z at q[0..4)
     */
    public static void toQuaternion(double[] r, int o, double[] q) {
        double[] xyzw = new double[4];
        shepperd(r, o, xyzw);
        double w = xyzw[3];
        double sign = w < 0 ? -1.0 : 1.0;
        q[0] = sign * w;
        q[1] = sign * xyzw[0];
        q[2] = sign * xyzw[1];
        q[3] = sign * xyzw[2];
    }

    /** Shepperd's method as SciPy implements it; writes a normalised (x, y, z, w). */
    private static void shepperd(double[] m, int o, double[] q) {
        double m00 = m[o];
        double m11 = m[o + 4];
        double m22 = m[o + 8];
        double trace = m00 + m11 + m22;
        int choice = 0;
        double best = m00;
        if (m11 > best) {
            choice = 1;
            best = m11;
        }
        if (m22 > best) {
            choice = 2;
            best = m22;
        }
        if (trace > best) {
            choice = 3;
        }
        switch (choice) {
            case 0 -> {
                q[0] = 1 - trace + 2 * m00;
                q[1] = m[o + 3] + m[o + 1];
                q[2] = m[o + 6] + m[o + 2];
                q[3] = m[o + 7] - m[o + 5];
            }
            case 1 -> {
                q[0] = m[o + 3] + m[o + 1];
                q[1] = 1 - trace + 2 * m11;
                q[2] = m[o + 7] + m[o + 5];
                q[3] = m[o + 2] - m[o + 6];
            }
            case 2 -> {
                q[0] = m[o + 6] + m[o + 2];
                q[1] = m[o + 7] + m[o + 5];
                q[2] = 1 - trace + 2 * m22;
                q[3] = m[o + 3] - m[o + 1];
            }
            default -> {
                q[0] = m[o + 7] - m[o + 5];
                q[1] = m[o + 2] - m[o + 6];
                q[2] = m[o + 3] - m[o + 1];
                q[3] = 1 + trace;
            }
        }
        double norm = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        for (int k = 0; k < 4; k++) {
            q[k] /= norm;
        }
    }

    /**
     * Rotation angle (rad, in [0, pi]) of the rotation matrix at {@code r[o]}: the norm of its
     * rotation vector (log map). Computed as SciPy does for evo (matrix -> quaternion -> rotation
     * vector), so angles agree with evo to the last digits; a matrix that is not orthogonal
     * within 1e-12 (e.g. a product of KITTI poses, orthonormal only to ~1e-6) is first replaced
     * by its nearest rotation (polar factor).
     */
    public static double angle(double[] r, int o) {
        return angle(r, o, new double[4]);
    }

    /**
     * {@link #angle(double[], int)} with caller-owned scratch space for the quaternion (hot loops
     * pass one array per thread instead of allocating one per call).
     *
     * @param q scratch, at least 4 long; overwritten
     */
    public static double angle(double[] r, int o, double[] q) {
        double[] m = r;
        int mo = o;
        if (!isOrthogonal(r, o)) {
            m = polarFactor(r, o);
            mo = 0;
        }
        shepperd(m, mo, q);
        if (q[3] < 0) {
            for (int k = 0; k < 4; k++) {
                q[k] = -q[k];
            }
        }
        double axNorm = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        double angle = 2 * StrictAtan2.atan2(axNorm, q[3]); // Math.atan2's bits, without its JNI call
        double scale = rotationVectorScale(angle);
        double vx = scale * q[0];
        double vy = scale * q[1];
        double vz = scale * q[2];
        return Math.sqrt(vx * vx + vy * vy + vz * vz);
    }

    /**
     * The factor s with rotation vector = s (x, y, z) for a unit quaternion (x, y, z, w) of angle
     * theta (rad): theta / sin(theta / 2), or its series 2 + theta^2 / 12 + 7 theta^4 / 2880 for
     * theta &lt;= 1e-3 (SciPy's {@code as_rotvec}); shared by {@link #angle} and {@link PlanarAngle}
     * so both compute it with the same operations.
     */
    static double rotationVectorScale(double angle) {
        if (angle <= 1e-3) {
            double a2 = angle * angle;
            return 2 + a2 / 12 + 7 * a2 * a2 / 2880;
        }
        return angle / Math.sin(angle / 2.0);
    }

    /** SciPy's test: R R^T close to I with atol 1e-12 and rtol 1e-5 (numpy isclose). */
    private static boolean isOrthogonal(double[] r, int o) {
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                double g = r[o + 3 * i] * r[o + 3 * j] + r[o + 3 * i + 1] * r[o + 3 * j + 1]
                        + r[o + 3 * i + 2] * r[o + 3 * j + 2];
                double e = (i == j) ? 1.0 : 0.0;
                if (!(Math.abs(g - e) <= 1e-12 + 1e-5 * Math.abs(e))) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * The nearest rotation (orthogonal polar factor U V^T) of a near-orthogonal matrix, by the
     * Newton iteration X <- (X + X^-T) / 2, which converges quadratically to the polar factor.
     */
    static double[] polarFactor(double[] r, int o) {
        double[] x = new double[9];
        System.arraycopy(r, o, x, 0, 9);
        double[] next = new double[9];
        for (int iter = 0; iter < 30; iter++) {
            double det = det(x, 0);
            if (det == 0.0 || !Double.isFinite(det)) {
                return x;
            }
            // inverse transpose = cofactor matrix / det
            double[] c = cofactor(x);
            double change = 0.0;
            for (int k = 0; k < 9; k++) {
                next[k] = 0.5 * (x[k] + c[k] / det);
                change = Math.max(change, Math.abs(next[k] - x[k]));
            }
            System.arraycopy(next, 0, x, 0, 9);
            if (change < 1e-17) {
                break;
            }
        }
        return x;
    }

    private static double[] cofactor(double[] m) {
        return new double[] {
            m[4] * m[8] - m[5] * m[7], m[5] * m[6] - m[3] * m[8], m[3] * m[7] - m[4] * m[6],
            m[2] * m[7] - m[1] * m[8], m[0] * m[8] - m[2] * m[6], m[1] * m[6] - m[0] * m[7],
            m[1] * m[5] - m[2] * m[4], m[2] * m[3] - m[0] * m[5], m[0] * m[4] - m[1] * m[3]};
    }

    /** @return the determinant of the 3x3 matrix at {@code m[o]} */
    public static double det(double[] m, int o) {
        return m[o] * (m[o + 4] * m[o + 8] - m[o + 5] * m[o + 7])
                - m[o + 1] * (m[o + 3] * m[o + 8] - m[o + 5] * m[o + 6])
                + m[o + 2] * (m[o + 3] * m[o + 7] - m[o + 4] * m[o + 6]);
    }

    /**
     * Spherical linear interpolation between unit quaternions q0 and q1 (w, x, y, z) at
     * fraction f in [0, 1], along the shorter arc, as transformations.py's
     * {@code quaternion_slerp} (used by evo) computes it.
     *
     * @param out receives (w, x, y, z)
     */
    public static void slerp(double[] q0, double[] q1, double f, double[] out) {
        slerp(q0, q1, f, out, 0);
    }

    /**
     * {@link #slerp(double[], double[], double, double[])} into {@code out[o..o+4)} (one
     * {@link Slerp}; keep one to interpolate many fractions on a segment).
     */
    public static void slerp(double[] q0, double[] q1, double f, double[] out, int o) {
        Slerp s = new Slerp();
        s.ends(q0[0], q0[1], q0[2], q0[3], q1[0], q1[1], q1[2], q1[3]);
        s.at(f, out, o);
    }

    /**
     * Heading of the rotation matrix at {@code r[o]}: the z angle of its static x-y-z Euler
     * decomposition, atan2(r10, r00) (rad); 0 in gimbal lock, as transformations.py does.
     */
    public static double yaw(double[] r, int o) {
        double cy = Math.sqrt(r[o] * r[o] + r[o + 3] * r[o + 3]);
        if (cy > EPS4) {
            return Math.atan2(r[o + 3], r[o]);
        }
        return 0.0;
    }

    /**
     * Pitch of the rotation matrix at {@code r[o]}: the y angle of its static x-y-z Euler
     * decomposition, atan2(-r20, sqrt(r00^2 + r10^2)) (rad), in [-pi/2, pi/2].
     */
    public static double pitch(double[] r, int o) {
        double cy = Math.sqrt(r[o] * r[o] + r[o + 3] * r[o + 3]);
        return Math.atan2(-r[o + 6], cy);
    }
}
