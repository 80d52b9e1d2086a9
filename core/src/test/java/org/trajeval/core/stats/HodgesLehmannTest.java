package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * References: a brute-force Python computation run by hand: the sorted Walsh averages, their
 * median ({@code numpy.median}), and the signed-rank null distribution by enumerating all 2^n sign
 * patterns of the ranks 1..n ({@code itertools.product}); k = 1 + max{c : P(T &lt;= c) &lt;= alpha/2},
 * interval [W_(k), W_(M+1-k)], achieved level 1 - 2 P(T &lt;= k-1). Asymptotic: k =
 * floor(M/2 - norm.isf(alpha/2) sqrt(n(n+1)(2n+1)/24) + 1/2) with SciPy.
 */
class HodgesLehmannTest {
    private static final double TIGHT = 1e-15;
    /** Ten differences with a zero and a tie (0.25 twice). */
    private static final double[] D = {0.3, -0.1, 0.25, 0.0, 0.4, 0.25, 0.12, -0.05, 0.33, 0.18};

    @Test
    void workedExampleByHand() {
        // d = (1, 2, 3): Walsh averages 1, 1.5, 2, 2, 2.5, 3; median 2
        assertEquals(2.0, HodgesLehmann.of(new double[] {1, 2, 3}, 0.95).estimate(), 0.0);
    }

    @Test
    void exactIntervalWithZerosAndTiesMatchesBruteForce() {
        HodgesLehmann.Result r = HodgesLehmann.of(D, 0.95);
        assertEquals(0.17500000000000002, r.estimate(), TIGHT);
        assertEquals(0.039999999999999994, r.interval().lower(), TIGHT);
        assertEquals(0.29000000000000004, r.interval().upper(), TIGHT);
        assertEquals(0.951171875, r.achievedLevel(), TIGHT);
        assertEquals(HodgesLehmann.Method.EXACT, r.method());
        HodgesLehmann.Result r90 = HodgesLehmann.of(D, 0.9);
        assertEquals(0.065, r90.interval().lower(), TIGHT);
        assertEquals(0.29000000000000004, r90.interval().upper(), TIGHT);
        assertEquals(0.916015625, r90.achievedLevel(), TIGHT);
    }

    @Test
    void oneAndTwoDifferencesGiveTheWholeRangeAndSayTheLevelIsNotReached() {
        HodgesLehmann.Result one = HodgesLehmann.of(new double[] {0.5}, 0.95);
        assertEquals(0.5, one.interval().lower(), 0.0);
        assertEquals(0.5, one.interval().upper(), 0.0);
        assertEquals(0.0, one.achievedLevel(), 0.0);
        HodgesLehmann.Result two = HodgesLehmann.of(new double[] {0.5, -0.2}, 0.95);
        assertEquals(0.15, two.estimate(), TIGHT);
        assertEquals(-0.2, two.interval().lower(), 0.0);
        assertEquals(0.5, two.interval().upper(), 0.0);
        assertEquals(0.5, two.achievedLevel(), 0.0);
        // n = 6 all positive: P(T <= 0) = 1/64 <= 0.025, k = 1: [min, max], achieved 1 - 2/64 = 0.96875
        HodgesLehmann.Result six = HodgesLehmann.of(new double[] {1, 2, 3, 4, 5, 6}, 0.95);
        assertEquals(3.5, six.estimate(), 0.0);
        assertEquals(1.0, six.interval().lower(), 0.0);
        assertEquals(6.0, six.interval().upper(), 0.0);
        assertEquals(0.96875, six.achievedLevel(), 0.0);
    }

    @Test
    void largeSamplesUseTheNormalApproximationOfTheOrderStatistic() {
        double[] d = new double[60];
        for (int i = 1; i <= 60; i++) {
            d[i - 1] = Math.sin(i) + 0.3;
        }
        HodgesLehmann.Result r = HodgesLehmann.of(d, 0.95);
        assertEquals(HodgesLehmann.Method.ASYMPTOTIC, r.method());
        // k = 649 of M = 1830
        assertEquals(0.31477138574252306, r.estimate(), 1e-15);
        assertEquals(0.1558665962553351, r.interval().lower(), 1e-15);
        assertEquals(0.509901505202034, r.interval().upper(), 1e-15);
    }

    @Test
    void allZeroDifferencesGiveZero() {
        HodgesLehmann.Result r = HodgesLehmann.of(new double[] {0, 0, 0, 0, 0, 0, 0, 0}, 0.95);
        assertEquals(0.0, r.estimate(), 0.0);
        assertEquals(0.0, r.interval().lower(), 0.0);
        assertEquals(0.0, r.interval().upper(), 0.0);
    }
}
