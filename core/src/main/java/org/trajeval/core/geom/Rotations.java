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
        unitQuaternion(r[o], r[o + 1], r[o + 2], r[o + 3], r[o + 4], r[o + 5], r[o + 6], r[o + 7], r[o + 8], xyzw);
        q[0] = xyzw[3];
        q[1] = xyzw[0];
        q[2] = xyzw[1];
        q[3] = xyzw[2];
    }

    /**
     * Shepperd's method as SciPy implements it, on the matrix [[m00, m01, m02], [m10, m11, m12],
     * [m20, m21, m22]]: the largest of trace, m00, m11, m22 picks the branch, the four terms of that
     * branch are divided by their norm, and all four are negated when w &lt; 0. Writes (x, y, z, w)
     * with w &gt;= 0 into {@code q[0..4)}. Straight-line code on locals: callers that allocate q
     * locally (as {@link #angle(double, double, double, double, double, double, double, double, double)}
     * does) have it replaced by registers by the JIT's escape analysis.
     */
    private static void unitQuaternion(double m00, double m01, double m02, double m10, double m11, double m12,
            double m20, double m21, double m22, double[] q) {
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
        double x;
        double y;
        double z;
        double w;
        switch (choice) {
            case 0 -> {
                x = 1 - trace + 2 * m00;
                y = m10 + m01;
                z = m20 + m02;
                w = m21 - m12;
            }
            case 1 -> {
                x = m10 + m01;
                y = 1 - trace + 2 * m11;
                z = m21 + m12;
                w = m02 - m20;
            }
            case 2 -> {
                x = m20 + m02;
                y = m21 + m12;
                z = 1 - trace + 2 * m22;
                w = m10 - m01;
            }
            default -> {
                x = m21 - m12;
                y = m02 - m20;
                z = m10 - m01;
                w = 1 + trace;
            }
        }
        double norm = Math.sqrt(x * x + y * y + z * z + w * w);
        x /= norm;
        y /= norm;
        z /= norm;
        w /= norm;
        if (w < 0) {
            x = -x;
            y = -y;
            z = -z;
            w = -w;
        }
        q[0] = x;
        q[1] = y;
        q[2] = z;
        q[3] = w;
    }

    /**
     * Rotation angle (rad, in [0, pi]) of the rotation matrix at {@code r[o]}: the norm of its
     * rotation vector (log map). Computed as SciPy does for evo (matrix -> quaternion -> rotation
     * vector), so angles agree with evo to the last digits; a matrix that is not orthogonal
     * within 1e-12 (e.g. a product of KITTI poses, orthonormal only to ~1e-6) is first replaced
     * by its nearest rotation (polar factor).
     */
    public static double angle(double[] r, int o) {
        return angle(r[o], r[o + 1], r[o + 2], r[o + 3], r[o + 4], r[o + 5], r[o + 6], r[o + 7], r[o + 8]);
    }

    /**
     * {@link #angle(double[], int)} of the matrix [[m00, m01, m02], [m10, m11, m12], [m20, m21, m22]]
     * given entry by entry, so that kernels holding a product in locals need not store it. The same
     * operations in the same order as the matrix form (orthogonality test, polar factor when it
     * fails, Shepperd's quaternion with w &gt;= 0, rotation vector), hence the same bits.
     *
     * <p>Example: +90 deg about +z, rows (0, -1, 0), (1, 0, 0), (0, 0, 1): trace 1 is the largest, so
     * q = (0, 0, 2, 2) / sqrt(8) and the angle is 2 atan2(1/sqrt(2), 1/sqrt(2)) = pi/2.
     */
    public static double angle(double m00, double m01, double m02, double m10, double m11, double m12,
            double m20, double m21, double m22) {
        double[] q = new double[4];
        unitQuaternionOf(m00, m01, m02, m10, m11, m12, m20, m21, m22, q);
        double angle = 2 * StrictAtan2.atan2(norm(q[0], q[1], q[2]), q[3]); // Math.atan2's bits, without its JNI call
        double scale = rotationVectorScale(angle);
        return norm(scale * q[0], scale * q[1], scale * q[2]);
    }

    /**
     * The angles (rad) of two matrices M and N given entry by entry, as two calls of
     * {@link #angle(double, double, double, double, double, double, double, double, double)} would
     * give them, into {@code out[o]} and {@code out[o + 1]}. The two computations are independent
     * chains of long latency (two square roots, four divisions, atan2, sin); taking them step by
     * step side by side lets the processor overlap them.
     */
    public static void angles(double m00, double m01, double m02, double m10, double m11, double m12, double m20,
            double m21, double m22, double n00, double n01, double n02, double n10, double n11, double n12,
            double n20, double n21, double n22, double[] out, int o) {
        double[] a = new double[4];
        double[] b = new double[4];
        unitQuaternionOf(m00, m01, m02, m10, m11, m12, m20, m21, m22, a);
        unitQuaternionOf(n00, n01, n02, n10, n11, n12, n20, n21, n22, b);
        double angleA = 2 * StrictAtan2.atan2(norm(a[0], a[1], a[2]), a[3]);
        double angleB = 2 * StrictAtan2.atan2(norm(b[0], b[1], b[2]), b[3]);
        double scaleA = rotationVectorScale(angleA);
        double scaleB = rotationVectorScale(angleB);
        out[o] = norm(scaleA * a[0], scaleA * a[1], scaleA * a[2]);
        out[o + 1] = norm(scaleB * b[0], scaleB * b[1], scaleB * b[2]);
    }

    /**
     * The unit quaternion (x, y, z, w), w &gt;= 0, of the matrix (of its polar factor when it is not
     * orthogonal) into {@code q[0..4)}: the first steps of {@link #angle(double[], int)}.
     */
    private static void unitQuaternionOf(double m00, double m01, double m02, double m10, double m11, double m12,
            double m20, double m21, double m22, double[] q) {
        if (isOrthogonal(m00, m01, m02, m10, m11, m12, m20, m21, m22)) {
            unitQuaternion(m00, m01, m02, m10, m11, m12, m20, m21, m22, q);
        } else {
            double[] p = polarFactor(new double[] {m00, m01, m02, m10, m11, m12, m20, m21, m22}, 0);
            unitQuaternion(p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8], q);
        }
    }

    /** @return sqrt(x^2 + y^2 + z^2), summed left to right */
    private static double norm(double x, double y, double z) {
        return Math.sqrt(x * x + y * y + z * z);
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

    /**
     * SciPy's test: R R^T close to I with atol 1e-12 and rtol 1e-5 (numpy isclose). R R^T is
     * symmetric bit for bit (entry (i, j) and (j, i) are the same products summed in the same
     * order), so its upper triangle decides.
     */
    private static boolean isOrthogonal(double m00, double m01, double m02, double m10, double m11, double m12,
            double m20, double m21, double m22) {
        double diag = 1e-12 + 1e-5 * Math.abs(1.0);
        double off = 1e-12 + 1e-5 * Math.abs(0.0);
        return Math.abs(m00 * m00 + m01 * m01 + m02 * m02 - 1.0) <= diag
                && Math.abs(m00 * m10 + m01 * m11 + m02 * m12 - 0.0) <= off
                && Math.abs(m00 * m20 + m01 * m21 + m02 * m22 - 0.0) <= off
                && Math.abs(m10 * m10 + m11 * m11 + m12 * m12 - 1.0) <= diag
                && Math.abs(m10 * m20 + m11 * m21 + m12 * m22 - 0.0) <= off
                && Math.abs(m20 * m20 + m21 * m21 + m22 * m22 - 1.0) <= diag;
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
