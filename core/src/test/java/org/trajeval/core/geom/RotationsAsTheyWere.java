package org.trajeval.core.geom;

/**
 * {@link Rotations#angle(double[], int)} and {@link Rotations#toQuaternion} as they were before the
 * straight-line kernel (main at 4e1def5): orthogonality test over all nine entries of R R^T,
 * Shepperd's method into an array, the quaternion normalised and flipped in place, and
 * {@link StrictMath#atan2} (the JDK's fdlibm) for the angle. Kept verbatim as the reference the
 * kernel is pinned to.
 */
public final class RotationsAsTheyWere {
    private RotationsAsTheyWere() {
    }

    /** @return the rotation angle (rad) of the matrix at r[o], computed as before the kernel */
    public static double angle(double[] r, int o) {
        double[] q = new double[4];
        double[] m = r;
        int mo = o;
        if (!isOrthogonal(r, o)) {
            m = Rotations.polarFactor(r, o);
            mo = 0;
        }
        shepperd(m, mo, q);
        if (q[3] < 0) {
            for (int k = 0; k < 4; k++) {
                q[k] = -q[k];
            }
        }
        double axNorm = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
        double angle = 2 * StrictMath.atan2(axNorm, q[3]);
        double scale;
        if (angle <= 1e-3) {
            double a2 = angle * angle;
            scale = 2 + a2 / 12 + 7 * a2 * a2 / 2880;
        } else {
            scale = angle / Math.sin(angle / 2.0);
        }
        double vx = scale * q[0];
        double vy = scale * q[1];
        double vz = scale * q[2];
        return Math.sqrt(vx * vx + vy * vy + vz * vz);
    }

    /** @param q receives the unit quaternion (w, x, y, z) with w &gt;= 0 of the matrix at r[o] */
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
}
