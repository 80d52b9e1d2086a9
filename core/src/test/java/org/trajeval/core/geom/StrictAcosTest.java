package org.trajeval.core.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class StrictAcosTest {
    /** The reference: what the JDK computes (C fdlibm); Math.acos, which the evaluation called before, equals it. */
    private static void assertSameBits(double x) {
        long want = Double.doubleToRawLongBits(StrictMath.acos(x));
        assertEquals(want, Double.doubleToRawLongBits(Math.acos(x)), () -> "Math.acos differs from StrictMath at " + x);
        assertEquals(want, Double.doubleToRawLongBits(StrictAcos.acos(x)),
                () -> "acos(" + x + " = 0x" + Long.toHexString(Double.doubleToRawLongBits(x)) + ")");
    }

    @Test
    void equalsStrictMathBitForBitOnEveryBranchAndEdge() {
        double[] edges = {1.0, -1.0, 0.0, -0.0, 0.5, -0.5, Math.nextUp(0.5), Math.nextDown(0.5), Math.nextUp(-0.5),
            Math.nextDown(-0.5), Math.nextDown(1.0), Math.nextUp(-1.0), 0x1p-57, -0x1p-57, 0x1p-56, 0x1p-58,
            Double.MIN_VALUE, -Double.MIN_VALUE, Double.MIN_NORMAL, 1e-300, Math.nextUp(1.0), Math.nextDown(-1.0), 2.0,
            -7.5, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Math.sqrt(0.5), 0.9999999999,
            0.1, -0.1, 0.7071, 0.99, -0.99};
        for (double x : edges) {
            assertSameBits(x);
        }
    }

    @Test
    void equalsStrictMathBitForBitOnSeededSamples() {
        SplittableRandom rnd = new SplittableRandom(20261123L);
        for (int i = 0; i < 200_000; i++) {
            assertSameBits(rnd.nextDouble(-1.0, 1.0)); // uniform over [-1, 1): the three branches
            // near +-1, where slerp's cosines of small rotations live: 1 - 10^-k for k up to 16
            double tail = Math.pow(10, -rnd.nextDouble(0, 16));
            assertSameBits(1.0 - tail);
            assertSameBits(-1.0 + tail);
            // tiny arguments around the |x| < 2^-57 cut
            assertSameBits(Math.scalb(rnd.nextDouble(-1.0, 1.0), -rnd.nextInt(40, 80)));
        }
    }

    @Test
    void givesTheTextbookAnglesAtTheirCosines() {
        // acos(1/2) = pi/3, acos(0) = pi/2, acos(-1) = pi (rad), by hand; within one ulp of the rounded angle
        assertEquals(Math.PI / 3, StrictAcos.acos(0.5), Math.ulp(Math.PI / 3));
        assertEquals(Math.PI / 2, StrictAcos.acos(0.0), Math.ulp(Math.PI / 2));
        assertEquals(Math.PI, StrictAcos.acos(-1.0), 0.0);
        assertEquals(0.0, StrictAcos.acos(1.0), 0.0);
    }
}
