package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class MedianIntervalTest {
    private static final double TOL = 1e-15;

    @Test
    void tenValuesAtNinetyFivePercentUseTheSecondAndNinthOrderStatistics() {
        // by hand: P(B <= 1) = 11/1024 <= 0.025 < P(B <= 2) = 56/1024, B ~ Bin(10, 1/2): k = 2,
        // interval [x_(2), x_(9)], achieved level 1 - 22/1024
        double[] v = {10, 1, 9, 2, 8, 3, 7, 4, 6, 5};
        MedianInterval.Result r = MedianInterval.of(v, 0.95);
        assertEquals(5.5, r.median(), TOL);
        assertEquals(2.0, r.interval().lower(), TOL);
        assertEquals(9.0, r.interval().upper(), TOL);
        assertEquals(1.0 - 22.0 / 1024.0, r.achievedLevel(), TOL);
    }

    @Test
    void tooFewValuesGiveTheRangeWithTheLowerAchievedLevel() {
        // n = 5: P(B <= 0) = 1/32 > 0.025, so the whole range, achieved level 1 - 2/32 = 0.9375
        MedianInterval.Result r = MedianInterval.of(new double[] {3, 1, 2, 5, 4}, 0.95);
        assertEquals(3.0, r.median(), TOL);
        assertEquals(1.0, r.interval().lower(), TOL);
        assertEquals(5.0, r.interval().upper(), TOL);
        assertEquals(0.9375, r.achievedLevel(), TOL);
    }

    @Test
    void manyValuesStayFiniteWhereTwoToTheMinusNUnderflows() {
        // n = 2001 > 1074: the binomial terms are built in log space; the interval brackets the median
        double[] v = new double[2001];
        for (int i = 0; i < v.length; i++) {
            v[i] = i;
        }
        MedianInterval.Result r = MedianInterval.of(v, 0.95);
        assertEquals(1000.0, r.median(), TOL);
        // normal approximation of k: n/2 - 1.96 sqrt(n)/2 = 956.2; the exact k is within one of it
        assertEquals(956.0, r.interval().lower(), 1.0);
        assertEquals(2000.0 - r.interval().lower(), r.interval().upper(), TOL);
    }
}
