package org.trajeval.core.geom;

/**
 * Rotation angle (rad, in [0, pi]) of a rotation about +z given by its upper-left 2x2 block
 * [[m00, m01], [m10, m11]]: bit for bit {@link Rotations#angle(double[], int)} of the
 * 3x3 matrix [[m00, m01, 0], [m10, m11, 0], [0, 0, 1]], with the operations on the exact zeros and
 * the one of that matrix left out.
 *
 * <p>Why the bits agree: the zeros (of either sign) only ever add a signed zero to a value or
 * multiply one, which changes no nonzero value; the sign of a zero result is lost in the squares,
 * the comparisons and atan2(y &gt; 0, +-0) = pi/2 that follow. With m22 = 1 the orthogonality test
 * reduces to |m00^2 + m01^2 - 1|, |m10^2 + m11^2 - 1| &lt;= 1e-12 + 1e-5 and
 * |m00 m10 + m01 m11| &lt;= 1e-12; Shepperd's trace is (m00 + m11) + 1. For a rotation about +z
 * (m00 = m11 = cos) Shepperd takes the trace branch (q = (0, 0, m10 - m01, 1 + trace)) or the
 * m22 branch (q = (0, 0, (1 - trace) + 2, m10 - m01)); the rotation vector is then (0, 0, v_z)
 * and the angle sqrt(v_z^2), which is |v_z| ({@link #rootOfSquare}). The other branches (m00 or
 * m11 the largest diagonal entry: only reflections or blocks far from orthogonal) and blocks that
 * fail the orthogonality test (which {@link Rotations#angle} first replaces by their polar factor)
 * go to {@link Rotations#angle} itself.
 *
 * <p>Example: the block of +90 deg about +z, [[0, -1], [1, 0]]: trace 1, q = (0, 0, 2, 2) / sqrt(8),
 * angle 2 atan2(1/sqrt(2), 1/sqrt(2)) = pi/2.
 */
public final class PlanarAngle {
    private PlanarAngle() {
    }

    /** @return the rotation angle (rad) of [[m00, m01, 0], [m10, m11, 0], [0, 0, 1]] as {@link Rotations#angle} */
    public static double of(double m00, double m01, double m10, double m11) {
        if (!shepperdAboutZ(m00, m01, m10, m11)) {
            return general(m00, m01, m10, m11);
        }
        double z = quaternionZ(m00, m01, m10, m11);
        double w = quaternionW(m00, m01, m10, m11);
        double norm = Math.sqrt(z * z + w * w);
        z /= norm;
        w /= norm;
        if (w < 0) {
            z = -z;
            w = -w;
        }
        double axNorm = rootOfSquare(z);
        double angle = 2 * StrictAtan2.atan2(axNorm, w); // Math.atan2's bits, without its JNI call
        double vz = Rotations.rotationVectorScale(angle) * z;
        return rootOfSquare(vz);
    }

    /**
     * The angles (rad) of two blocks M and N into {@code out[o]} and {@code out[o + 1]}, as two
     * calls of {@link #of} would give them: the same steps, taken side by side so that the processor
     * overlaps the two chains of long latency (a square root, two divisions, atan2, a sine each).
     */
    public static void two(double m00, double m01, double m10, double m11, double n00, double n01, double n10,
            double n11, double[] out, int o) {
        if (!shepperdAboutZ(m00, m01, m10, m11) || !shepperdAboutZ(n00, n01, n10, n11)) {
            out[o] = of(m00, m01, m10, m11);
            out[o + 1] = of(n00, n01, n10, n11);
            return;
        }
        double za = quaternionZ(m00, m01, m10, m11);
        double wa = quaternionW(m00, m01, m10, m11);
        double zb = quaternionZ(n00, n01, n10, n11);
        double wb = quaternionW(n00, n01, n10, n11);
        double norma = Math.sqrt(za * za + wa * wa);
        double normb = Math.sqrt(zb * zb + wb * wb);
        za /= norma;
        zb /= normb;
        wa /= norma;
        wb /= normb;
        if (wa < 0) {
            za = -za;
            wa = -wa;
        }
        if (wb < 0) {
            zb = -zb;
            wb = -wb;
        }
        double anglea = 2 * StrictAtan2.atan2(rootOfSquare(za), wa);
        double angleb = 2 * StrictAtan2.atan2(rootOfSquare(zb), wb);
        double vza = Rotations.rotationVectorScale(anglea) * za;
        double vzb = Rotations.rotationVectorScale(angleb) * zb;
        out[o] = rootOfSquare(vza);
        out[o + 1] = rootOfSquare(vzb);
    }

    /**
     * @return true when the block passes the orthogonality test and Shepperd takes its trace or
     *     m22 branch (the quaternion (0, 0, {@link #quaternionZ}, {@link #quaternionW}) before
     *     normalisation); false for the cases {@link Rotations#angle} itself computes
     */
    private static boolean shepperdAboutZ(double m00, double m01, double m10, double m11) {
        double tol = 1e-12 + 1e-5 * Math.abs(1.0);
        if (!(Math.abs(m00 * m00 + m01 * m01 - 1.0) <= tol) || !(Math.abs(m10 * m10 + m11 * m11 - 1.0) <= tol)
                || !(Math.abs(m00 * m10 + m01 * m11) <= 1e-12)) {
            return false;
        }
        double trace = m00 + m11 + 1.0;
        double best = Math.max(m00, m11);
        return 1.0 > best || trace > best; // else Shepperd's m00 or m11 branch
    }

    /** Shepperd's unnormalised z of a block {@link #shepperdAboutZ} accepts: trace branch m10 - m01, m22 branch (1 - trace) + 2. */
    private static double quaternionZ(double m00, double m01, double m10, double m11) {
        double trace = m00 + m11 + 1.0;
        return traceBranch(m00, m11, trace) ? m10 - m01 : 1 - trace + 2.0;
    }

    /** Shepperd's unnormalised w of a block {@link #shepperdAboutZ} accepts: trace branch 1 + trace, m22 branch m10 - m01. */
    private static double quaternionW(double m00, double m01, double m10, double m11) {
        double trace = m00 + m11 + 1.0;
        return traceBranch(m00, m11, trace) ? 1 + trace : m10 - m01;
    }

    /** @return true for Shepperd's trace branch, false for its m22 branch */
    private static boolean traceBranch(double m00, double m11, double trace) {
        return !(1.0 > Math.max(m00, m11)) || trace > 1.0;
    }

    /**
     * {@code Math.sqrt(x * x)} bit for bit, without the square root where it is not needed: |x| when
     * 2^-511 &lt;= |x| &lt;= 2^511, else the square root of the rounded square.
     *
     * <p>Why |x| is exact there (binary64, round to nearest): write |x| = m 2^e with 1 &lt;= m &lt;= 2 - 2^-52.
     * In that range x^2 is a normal number (at least 2^-1022, at most 2^1022), so the product is rounded
     * with relative error at most u = 2^-53 / (1 + 2^-53): fl(x^2) = m^2 2^2e (1 + d), |d| &lt;= u. Its exact
     * square root is m 2^e sqrt(1 + d), which differs from |x| by at most m 2^e (u / 2)(1 + u) &lt;
     * 2^e 2^-53: less than half the spacing 2^(e-52) of the doubles around |x|, so the rounded root is
     * |x| itself. Below 2^-511 the square is subnormal or zero and loses bits (x = 2^-537 + 2^-589:
     * sqrt(x * x) = 2^-537), so there, as beyond 2^511 where the square overflows, the root is taken.
     * Signed zeros and NaN take the root too: sqrt(+-0 * +-0) = +0.
     */
    static double rootOfSquare(double x) {
        double a = Math.abs(x);
        return a >= 0x1p-511 && a <= 0x1p511 ? a : Math.sqrt(x * x);
    }

    private static double general(double m00, double m01, double m10, double m11) {
        return Rotations.angle(m00, m01, 0.0, m10, m11, 0.0, 0.0, 0.0, 1.0);
    }
}
