package org.trajeval.core.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class StrictAtan2Test {
    /** The reference: what the JDK computes (C fdlibm); Math.atan2, which the evaluation called before, equals it. */
    private static void assertSameBits(double y, double x) {
        if (Double.isNaN(y) || Double.isNaN(x)) {
            // NaN in, NaN out; which NaN the hardware returns is not specified (nor used)
            assertEquals(Double.isNaN(StrictMath.atan2(y, x)), Double.isNaN(StrictAtan2.atan2(y, x)));
            return;
        }
        long want = Double.doubleToRawLongBits(StrictMath.atan2(y, x));
        assertEquals(want, Double.doubleToRawLongBits(Math.atan2(y, x)),
                () -> "Math.atan2 differs from StrictMath at " + y + ", " + x);
        assertEquals(want, Double.doubleToRawLongBits(StrictAtan2.atan2(y, x)),
                () -> "atan2(" + y + ", " + x + ") = " + StrictMath.atan2(y, x) + ", got " + StrictAtan2.atan2(y, x));
    }

    @Test
    void equalsStrictMathBitForBitOnSpecialValues() {
        double[] v = {0.0, -0.0, 1.0, -1.0, Double.MIN_VALUE, -Double.MIN_VALUE, Double.MIN_NORMAL, Double.MAX_VALUE,
            -Double.MAX_VALUE, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NaN, 0.5, 2.0, 1e-300, 1e300,
            Math.nextUp(1.0), Math.nextDown(1.0), 0x1p-29, 0x1p66, 0x1p60, 0x1p-60, 3.0, -3.0, 7.0 / 16, 11.0 / 16,
            19.0 / 16, 39.0 / 16, Math.PI};
        for (double y : v) {
            for (double x : v) {
                assertSameBits(y, x);
                assertSameBits(-y, x);
                assertSameBits(y, -x);
            }
        }
    }

    @Test
    void equalsStrictMathBitForBitOnSeededSamples() {
        SplittableRandom rnd = new SplittableRandom(20261125L);
        double[] cuts = {7.0 / 16, 11.0 / 16, 19.0 / 16, 39.0 / 16, 0x1p-29, 0x1p66};
        for (int i = 0; i < 300_000; i++) {
            // the unit square, where sines and cosines live
            assertSameBits(rnd.nextDouble(-1.0, 1.0), rnd.nextDouble(-1.0, 1.0));
            // any magnitudes: the exponent difference decides the |y/x| > 2^60 and < -2^60 branches
            assertSameBits(Math.scalb(rnd.nextDouble(-1.0, 1.0), rnd.nextInt(-1074, 1024)),
                    Math.scalb(rnd.nextDouble(-1.0, 1.0), rnd.nextInt(-1074, 1024)));
            assertSameBits(Math.scalb(rnd.nextDouble(-1.0, 1.0), rnd.nextInt(-70, 70)),
                    Math.scalb(rnd.nextDouble(-1.0, 1.0), rnd.nextInt(-70, 70)));
            // ratios at the reduction cuts of atan, within a few ulps either side
            double c = cuts[rnd.nextInt(cuts.length)];
            double x = rnd.nextDouble(0.1, 10.0);
            double y = c * x;
            for (int u = -2; u <= 2; u++) {
                double yy = y + u * Math.ulp(y);
                assertSameBits(yy, x);
                assertSameBits(-yy, -x);
            }
            // x = 1 (fdlibm goes straight to atan(y)) and y near 0 against x near 0
            assertSameBits(rnd.nextDouble(-10.0, 10.0), 1.0);
            assertSameBits(rnd.nextDouble(-1e-8, 1e-8), rnd.nextDouble(-1.0, 1.0));
        }
    }

    @Test
    void givesTheTextbookAnglesOfTheAxesAndDiagonals() {
        // by hand: (1, 1) at pi/4, (0, 1) at pi/2, (-1, 0) at pi, (-1, -1) at -3 pi/4 (rad)
        assertEquals(Math.PI / 4, StrictAtan2.atan2(1.0, 1.0), Math.ulp(Math.PI / 4));
        assertEquals(Math.PI / 2, StrictAtan2.atan2(1.0, 0.0), Math.ulp(Math.PI / 2));
        assertEquals(Math.PI, StrictAtan2.atan2(0.0, -1.0), Math.ulp(Math.PI));
        assertEquals(-3 * Math.PI / 4, StrictAtan2.atan2(-1.0, -1.0), Math.ulp(Math.PI));
    }
}
