package org.trajeval.core.geom;

/**
 * The arc cosine with exactly the bits of {@link StrictMath#acos} (and of {@link Math#acos}, which
 * on JDK 17 calls it), computed in Java: fdlibm's {@code __ieee754_acos} (e_acos.c, Sun
 * Microsystems 1993: "Permission to use, copy, modify, and distribute this software is freely
 * granted, provided that this notice is preserved"), step for step.
 *
 * <p>Why: JDK 17's {@code StrictMath.acos} is the C fdlibm behind a JNI call, and for
 * |x| &gt; 0.5 fdlibm takes its square root with its own bit-by-bit software routine, about
 * 0.4-0.9 us a call on this machine (a quaternion slerp per interpolated pose is 10^4 calls per
 * 10^4-pose run). The square root is correctly rounded in both (IEEE 754), so {@link Math#sqrt}
 * (one instruction) gives the same bits; every other step is the same double arithmetic in the
 * same order. {@code StrictAcosTest} compares the bits with {@code StrictMath.acos} on every branch.
 *
 * <p>Method (fdlibm's comment): acos(x) = pi/2 - asin(x), with asin(x) = x + x*x^2*R(x^2) for
 * |x| &lt; 0.5, R a rational approximation; for x &gt; 0.5, acos(x) = 2 asin(sqrt((1-x)/2)),
 * with the square root split into a high part (low word zeroed) and a correction; for x &lt; -0.5,
 * acos(x) = pi - 2 asin(sqrt((1+x)/2)). acos(1) = 0, acos(-1) = pi, NaN outside [-1, 1].
 */
public final class StrictAcos {
    private static final double PI = Double.longBitsToDouble(0x400921FB54442D18L);
    private static final double PIO2_HI = Double.longBitsToDouble(0x3FF921FB54442D18L);
    private static final double PIO2_LO = Double.longBitsToDouble(0x3C91A62633145C07L);
    private static final double PS0 = Double.longBitsToDouble(0x3FC5555555555555L);
    private static final double PS1 = Double.longBitsToDouble(0xBFD4D61203EB6F7DL);
    private static final double PS2 = Double.longBitsToDouble(0x3FC9C1550E884455L);
    private static final double PS3 = Double.longBitsToDouble(0xBFA48228B5688F3BL);
    private static final double PS4 = Double.longBitsToDouble(0x3F49EFE07501B288L);
    private static final double PS5 = Double.longBitsToDouble(0x3F023DE10DFDF709L);
    private static final double QS1 = Double.longBitsToDouble(0xC0033A271C8A2D4BL);
    private static final double QS2 = Double.longBitsToDouble(0x40002AE59C598AC8L);
    private static final double QS3 = Double.longBitsToDouble(0xBFE6066C1B8D0159L);
    private static final double QS4 = Double.longBitsToDouble(0x3FB3B8C5B12E9282L);

    private StrictAcos() {
    }

    /**
     * @param x cosine, in [-1, 1]
     * @return the angle in [0, pi] (rad) whose cosine is x, bit for bit {@code StrictMath.acos(x)};
     *     NaN for NaN or |x| &gt; 1
     */
    public static double acos(double x) {
        long bits = Double.doubleToRawLongBits(x);
        int hx = (int) (bits >> 32);
        int lx = (int) bits;
        int ix = hx & 0x7fffffff;
        if (ix >= 0x3ff00000) { // |x| >= 1
            if (((ix - 0x3ff00000) | lx) == 0) { // |x| == 1
                return hx > 0 ? 0.0 : PI + 2.0 * PIO2_LO;
            }
            return (x - x) / (x - x); // NaN
        }
        if (ix < 0x3fe00000) { // |x| < 0.5
            if (ix <= 0x3c600000) { // |x| < 2^-57
                return PIO2_HI + PIO2_LO;
            }
            double z = x * x;
            double r = p(z) / q(z);
            return PIO2_HI - (x - (PIO2_LO - x * r));
        } else if (hx < 0) { // x < -0.5
            double z = (1.0 + x) * 0.5;
            double p = p(z);
            double q = q(z);
            double s = Math.sqrt(z);
            double r = p / q;
            double w = r * s - PIO2_LO;
            return PI - 2.0 * (s + w);
        } else { // x > 0.5
            double z = (1.0 - x) * 0.5;
            double s = Math.sqrt(z);
            double df = Double.longBitsToDouble(Double.doubleToRawLongBits(s) & 0xffffffff00000000L);
            double c = (z - df * df) / (s + df);
            double r = p(z) / q(z);
            double w = r * s + c;
            return 2.0 * (df + w);
        }
    }

    private static double p(double z) {
        return z * (PS0 + z * (PS1 + z * (PS2 + z * (PS3 + z * (PS4 + z * PS5)))));
    }

    private static double q(double z) {
        return 1.0 + z * (QS1 + z * (QS2 + z * (QS3 + z * QS4)));
    }
}
