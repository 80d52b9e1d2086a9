package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class WilcoxonSignedRankTest {
    private static final double TIGHT = 1e-12;

    @Test
    void smallExampleByHand() {
        // d = (1, -2, 3, 4, 5): ranks 1..5, W+ = 13, W- = 2. Subsets of {1..5} with sum <= 2:
        // {}, {1}, {2} -> 3 of 32 sign assignments, two-sided p = 6/32 = 0.1875.
        WilcoxonSignedRank.Result r = WilcoxonSignedRank.test(new double[] {1, -2, 3, 4, 5});
        assertEquals(13.0, r.wPlus(), TIGHT);
        assertEquals(2.0, r.wMinus(), TIGHT);
        assertEquals(0.1875, r.pValue(), TIGHT);
        assertEquals(WilcoxonSignedRank.Method.EXACT, r.method());
    }

    @Test
    void zerosAreDroppedAndTiesGetMidRanks() {
        // d = (0, 2, -2, 3): zero dropped, |d| = 2, 2, 3 -> ranks 1.5, 1.5, 3; W+ = 4.5, W- = 1.5.
        // Doubled ranks 3, 3, 6 (total 12); doubled W+ = 9. Sign assignments (8) with doubled sum
        // >= 9: {3,6}x2 = 9, {3,3,6} = 12 -> 3; with sum <= 9: all but the one of 12 -> 7.
        // p = 2 * 3/8 = 0.75.
        WilcoxonSignedRank.Result r = WilcoxonSignedRank.test(new double[] {0, 2, -2, 3});
        assertEquals(3, r.n());
        assertEquals(1, r.zeros());
        assertEquals(4.5, r.wPlus(), TIGHT);
        assertEquals(1.5, r.wMinus(), TIGHT);
        assertEquals(0.75, r.pValue(), TIGHT);
    }

    @Test
    void allPositiveGivesTheSmallestExactP() {
        // n = 6, all positive: only 1 of 64 assignments is as extreme on each side: p = 2/64
        WilcoxonSignedRank.Result r = WilcoxonSignedRank.test(new double[] {0.1, 0.2, 0.3, 0.4, 0.5, 0.6});
        assertEquals(2.0 / 64.0, r.pValue(), TIGHT);
    }

    @Test
    void exactPAgreesWithCommonsMathWithoutTies() {
        org.apache.commons.math3.stat.inference.WilcoxonSignedRankTest cm =
                new org.apache.commons.math3.stat.inference.WilcoxonSignedRankTest();
        SplittableRandom rng = new SplittableRandom(5);
        for (int trial = 0; trial < 40; trial++) {
            int n = 3 + rng.nextInt(20);
            double[] x = new double[n];
            double[] y = new double[n];
            double[] d = new double[n];
            for (int i = 0; i < n; i++) {
                x[i] = rng.nextDouble();
                y[i] = rng.nextDouble() + 0.1;
                d[i] = x[i] - y[i];
            }
            assertEquals(cm.wilcoxonSignedRankTest(x, y, true), WilcoxonSignedRank.test(d).pValue(), 1e-12);
        }
    }

    @Test
    void normalApproximationIsCloseToCommonsMathExactPAtN30() {
        // Commons Math 3.6.1's own asymptotic p uses z = (W_min - E - 0.5)/sd, a continuity correction
        // in the wrong direction, so we check our approximation against its exact p instead:
        // at n = 30 the corrected normal approximation is within 0.01 of the exact tail.
        org.apache.commons.math3.stat.inference.WilcoxonSignedRankTest cm =
                new org.apache.commons.math3.stat.inference.WilcoxonSignedRankTest();
        SplittableRandom rng = new SplittableRandom(9);
        for (int trial = 0; trial < 5; trial++) {
            int n = 20;
            double[] x = new double[n];
            double[] y = new double[n];
            double[] d = new double[n];
            for (int i = 0; i < n; i++) {
                x[i] = rng.nextDouble();
                y[i] = rng.nextDouble() + 0.1;
                d[i] = x[i] - y[i];
            }
            WilcoxonSignedRank.Result r = WilcoxonSignedRank.normalApproximation(d);
            assertEquals(WilcoxonSignedRank.Method.NORMAL_APPROXIMATION, r.method());
            assertEquals(cm.wilcoxonSignedRank(x, y), Math.max(r.wPlus(), r.wMinus()), 1e-12);
            assertEquals(cm.wilcoxonSignedRankTest(x, y, true), r.pValue(), 0.01);
        }
    }

    @Test
    void normalApproximationByHand() {
        // n = 60 positive differences 1..60, one negative: d = 1..60 with d_1 negated.
        // W- = 1, E = 60*61/4 = 915, Var = 60*61*121/24 = 18452.5, z = (914 - 0.5)/sqrt(18452.5)
        double[] d = new double[60];
        for (int i = 0; i < 60; i++) {
            d[i] = i + 1;
        }
        d[0] = -1;
        WilcoxonSignedRank.Result r = WilcoxonSignedRank.test(d);
        double z = 913.5 / Math.sqrt(18452.5);
        double p = 2.0 * (1.0 - new org.apache.commons.math3.distribution.NormalDistribution().cumulativeProbability(z));
        assertEquals(WilcoxonSignedRank.Method.NORMAL_APPROXIMATION, r.method());
        assertEquals(1.0, r.wMinus(), TIGHT);
        assertEquals(p, r.pValue(), 1e-15);
    }

    @Test
    void noNonZeroDifferenceGivesPOne() {
        WilcoxonSignedRank.Result r = WilcoxonSignedRank.test(new double[] {0, 0});
        assertEquals(1.0, r.pValue(), 0.0);
        assertEquals(WilcoxonSignedRank.Method.NO_NONZERO_DIFFERENCES, r.method());
    }

    @Test
    void normalApproximationKeepsTheTailDigits() {
        // 51 positive distinct differences: W+ = 1326, E = 663, Var = 51*52*103/24 = 11381.5,
        // z = 662.5 / sqrt(11381.5) = 6.20992179995745; p = erfc(z / sqrt 2) by mpmath at 50 digits:
        // 5.3010974667060379946e-10 (the old 2(1 - Phi(z)) gave 5.301097339e-10)
        double[] d = new double[51];
        for (int i = 0; i < d.length; i++) {
            d[i] = i + 1.0;
        }
        WilcoxonSignedRank.Result r = WilcoxonSignedRank.test(d);
        assertEquals(WilcoxonSignedRank.Method.NORMAL_APPROXIMATION, r.method());
        assertEquals(5.3010974667060379946e-10, r.pValue(), 1e-12 * 5.3010974667060379946e-10);
    }
}
