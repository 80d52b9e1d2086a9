package org.trajeval.core.geom;

/**
 * The two-argument arc tangent with exactly the bits of {@link StrictMath#atan2} (and of
 * {@link Math#atan2}, which on JDK 17 calls it), computed in Java: fdlibm's
 * {@code __ieee754_atan2} and {@code atan} (e_atan2.c, s_atan.c, Sun Microsystems 1993:
 * "Permission to use, copy, modify, and distribute this software is freely granted, provided that
 * this notice is preserved"), step for step.
 *
 * <p>Why: JDK 17's {@code StrictMath.atan2} is the C fdlibm behind a JNI call, 40-55 ns a call on
 * this machine against 10-15 ns for the intrinsic {@code Math.sin}; the planar evaluation calls it
 * about three times per pose (the interpolated reference's yaw and the ATE and RPE angles).
 * Every step here is the same double arithmetic in the same order, so the bits agree;
 * {@code StrictAtan2Test} compares them with {@code StrictMath.atan2} on every branch.
 *
 * <p>Method (fdlibm's comment): atan2(y, x) = +-atan(|y/x|) for x &gt; 0 and
 * +-(pi - atan(|y/x|)) for x &lt; 0, with the special cases of zeros and infinities; atan(t) is
 * reduced to [0, 7/16] by atan(t) = atan(c) + atan((t - c) / (1 + c t)) for c = 1/2, 1, 3/2, or
 * atan(t) = pi/2 + atan(-1/t) beyond 39/16, and there evaluated as t - t^3 P(t^2), P of degree 10
 * split into odd and even parts.
 */
public final class StrictAtan2 {
    private static final double TINY = 1.0e-300;
    private static final double PI_O_4 = Double.longBitsToDouble(0x3FE921FB54442D18L);
    private static final double PI_O_2 = Double.longBitsToDouble(0x3FF921FB54442D18L);
    private static final double PI = Double.longBitsToDouble(0x400921FB54442D18L);
    private static final double PI_LO = Double.longBitsToDouble(0x3CA1A62633145C07L);
    private static final double[] ATAN_HI = {
        Double.longBitsToDouble(0x3FDDAC670561BB4FL), // atan(0.5) hi
        Double.longBitsToDouble(0x3FE921FB54442D18L), // atan(1.0) hi
        Double.longBitsToDouble(0x3FEF730BD281F69BL), // atan(1.5) hi
        Double.longBitsToDouble(0x3FF921FB54442D18L), // atan(inf) hi
    };
    private static final double[] ATAN_LO = {
        Double.longBitsToDouble(0x3C7A2B7F222F65E2L),
        Double.longBitsToDouble(0x3C81A62633145C07L),
        Double.longBitsToDouble(0x3C7007887AF0CBBDL),
        Double.longBitsToDouble(0x3C91A62633145C07L),
    };
    private static final double AT0 = Double.longBitsToDouble(0x3FD555555555550DL);
    private static final double AT1 = Double.longBitsToDouble(0xBFC999999998EBC4L);
    private static final double AT2 = Double.longBitsToDouble(0x3FC24924920083FFL);
    private static final double AT3 = Double.longBitsToDouble(0xBFBC71C6FE231671L);
    private static final double AT4 = Double.longBitsToDouble(0x3FB745CDC54C206EL);
    private static final double AT5 = Double.longBitsToDouble(0xBFB3B0F2AF749A6DL);
    private static final double AT6 = Double.longBitsToDouble(0x3FB10D66A0D03D51L);
    private static final double AT7 = Double.longBitsToDouble(0xBFADDE2D52DEFD9AL);
    private static final double AT8 = Double.longBitsToDouble(0x3FA97B4B24760DEBL);
    private static final double AT9 = Double.longBitsToDouble(0xBFA2B4442C6A6C2FL);
    private static final double AT10 = Double.longBitsToDouble(0x3F90AD3AE322DA11L);

    private StrictAtan2() {
    }

    /**
     * @return the angle (rad, in [-pi, pi]) of the point (x, y), bit for bit
     *     {@code StrictMath.atan2(y, x)}; NaN when x or y is NaN (which NaN is not specified)
     */
    public static double atan2(double y, double x) {
        long bx = Double.doubleToRawLongBits(x);
        long by = Double.doubleToRawLongBits(y);
        int hx = (int) (bx >> 32);
        int lx = (int) bx;
        int hy = (int) (by >> 32);
        int ly = (int) by;
        int ix = hx & 0x7fffffff;
        int iy = hy & 0x7fffffff;
        if (x != x || y != y) {
            return x + y; // NaN
        }
        if (((hx - 0x3ff00000) | lx) == 0) {
            return atan(y); // x = 1
        }
        int m = ((hy >> 31) & 1) | ((hx >> 30) & 2); // 2 sign(x) + sign(y)
        if ((iy | ly) == 0) { // y = +-0
            switch (m) {
                case 0, 1:
                    return y;
                case 2:
                    return PI + TINY;
                default:
                    return -PI - TINY;
            }
        }
        if ((ix | lx) == 0) { // x = +-0
            return hy < 0 ? -PI_O_2 - TINY : PI_O_2 + TINY;
        }
        if (ix == 0x7ff00000) { // x = +-inf
            if (iy == 0x7ff00000) {
                switch (m) {
                    case 0:
                        return PI_O_4 + TINY;
                    case 1:
                        return -PI_O_4 - TINY;
                    case 2:
                        return 3.0 * PI_O_4 + TINY;
                    default:
                        return -3.0 * PI_O_4 - TINY;
                }
            }
            switch (m) {
                case 0:
                    return 0.0;
                case 1:
                    return -0.0;
                case 2:
                    return PI + TINY;
                default:
                    return -PI - TINY;
            }
        }
        if (iy == 0x7ff00000) { // y = +-inf
            return hy < 0 ? -PI_O_2 - TINY : PI_O_2 + TINY;
        }
        int k = (iy - ix) >> 20;
        double z;
        if (k > 60) { // |y/x| > 2^60
            z = PI_O_2 + 0.5 * PI_LO;
        } else if (hx < 0 && k < -60) { // |y|/x < -2^60
            z = 0.0;
        } else {
            z = atan(Math.abs(y / x));
        }
        switch (m) {
            case 0:
                return z;
            case 1:
                return -z;
            case 2:
                return PI - (z - PI_LO);
            default:
                return (z - PI_LO) - PI;
        }
    }

    /** fdlibm's {@code atan(x)} (rad). */
    static double atan(double x) {
        int hx = (int) (Double.doubleToRawLongBits(x) >> 32);
        int ix = hx & 0x7fffffff;
        int id;
        if (ix >= 0x44100000) { // |x| >= 2^66
            if (x != x) {
                return x + x; // NaN
            }
            return hx > 0 ? ATAN_HI[3] + ATAN_LO[3] : -ATAN_HI[3] - ATAN_LO[3];
        }
        if (ix < 0x3fdc0000) { // |x| < 0.4375
            if (ix < 0x3e200000) { // |x| < 2^-29
                return x;
            }
            id = -1;
        } else {
            x = Math.abs(x);
            if (ix < 0x3ff30000) { // |x| < 1.1875
                if (ix < 0x3fe60000) { // 7/16 <= |x| < 11/16
                    id = 0;
                    x = (2.0 * x - 1.0) / (2.0 + x);
                } else { // 11/16 <= |x| < 19/16
                    id = 1;
                    x = (x - 1.0) / (x + 1.0);
                }
            } else if (ix < 0x40038000) { // |x| < 2.4375
                id = 2;
                x = (x - 1.5) / (1.0 + 1.5 * x);
            } else { // 2.4375 <= |x| < 2^66
                id = 3;
                x = -1.0 / x;
            }
        }
        double z = x * x;
        double w = z * z;
        double s1 = z * (AT0 + w * (AT2 + w * (AT4 + w * (AT6 + w * (AT8 + w * AT10)))));
        double s2 = w * (AT1 + w * (AT3 + w * (AT5 + w * (AT7 + w * AT9))));
        if (id < 0) {
            return x - x * (s1 + s2);
        }
        z = ATAN_HI[id] - ((x * (s1 + s2) - ATAN_LO[id]) - x);
        return hx < 0 ? -z : z;
    }
}
