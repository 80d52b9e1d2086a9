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
 * and the angle sqrt(v_z^2). The other branches (m00 or m11 the largest diagonal entry: only
 * reflections or blocks far from orthogonal) and blocks that fail the orthogonality test (which
 * {@link Rotations#angle} first replaces by their polar factor) go to {@link Rotations#angle}
 * itself.
 *
 * <p>Example: the block of +90 deg about +z, [[0, -1], [1, 0]]: trace 1, q = (0, 0, 2, 2) / sqrt(8),
 * angle 2 atan2(1/sqrt(2), 1/sqrt(2)) = pi/2.
 */
public final class PlanarAngle {
    private PlanarAngle() {
    }

    /** @return the rotation angle (rad) of [[m00, m01, 0], [m10, m11, 0], [0, 0, 1]] as {@link Rotations#angle} */
    public static double of(double m00, double m01, double m10, double m11) {
        double tol = 1e-12 + 1e-5 * Math.abs(1.0);
        if (!(Math.abs(m00 * m00 + m01 * m01 - 1.0) <= tol) || !(Math.abs(m10 * m10 + m11 * m11 - 1.0) <= tol)
                || !(Math.abs(m00 * m10 + m01 * m11) <= 1e-12)) {
            return general(m00, m01, m10, m11);
        }
        double trace = m00 + m11 + 1.0;
        double best = Math.max(m00, m11);
        if (!(1.0 > best) && !(trace > best)) {
            return general(m00, m01, m10, m11); // Shepperd's m00 or m11 branch
        }
        double z;
        double w;
        if (!(1.0 > best) || trace > 1.0) { // Shepperd's trace branch (else its m22 branch)
            z = m10 - m01;
            w = 1 + trace;
        } else {
            z = 1 - trace + 2.0;
            w = m10 - m01;
        }
        double norm = Math.sqrt(z * z + w * w);
        z /= norm;
        w /= norm;
        if (w < 0) {
            z = -z;
            w = -w;
        }
        double axNorm = Math.sqrt(z * z);
        double angle = 2 * StrictAtan2.atan2(axNorm, w); // Math.atan2's bits, without its JNI call
        double vz = Rotations.rotationVectorScale(angle) * z;
        return Math.sqrt(vz * vz);
    }

    private static double general(double m00, double m01, double m10, double m11) {
        return Rotations.angle(m00, m01, 0.0, m10, m11, 0.0, 0.0, 0.0, 1.0);
    }
}
