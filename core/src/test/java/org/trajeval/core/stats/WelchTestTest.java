package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/**
 * Reference values from SciPy 1.10.1 (Debian python3-scipy):
 * {@code stats.ttest_ind_from_stats(m1, s1, n1, m2, s2, n2, equal_var=False, alternative='greater')}
 * and {@code stats.t.interval(level, n - 1, loc=mean, scale=sd / sqrt(n))}.
 */
class WelchTestTest {
    private static final double P_TOL = 1e-9;

    @Test
    void equalSizesAndVariancesMatchScipy() {
        // ttest_ind_from_stats(1.2, 0.2, 10, 1.0, 0.2, 10, equal_var=False, alternative='greater')
        assertEquals(0.019124807258056962, WelchTest.greater(10, 1.2, 0.04, 10, 1.0, 0.04), P_TOL);
    }

    @Test
    void unequalSizesAndVariancesUseWelchSatterthwaiteDegreesOfFreedom() {
        // ttest_ind_from_stats(1.1, 0.3, 5, 1.0, 0.1, 12, equal_var=False, alternative='greater')
        assertEquals(0.2516472189707142, WelchTest.greater(5, 1.1, 0.09, 12, 1.0, 0.01), P_TOL);
    }

    @Test
    void theOtherDirectionIsTheComplement() {
        double p = WelchTest.greater(10, 1.2, 0.04, 10, 1.0, 0.04);
        assertEquals(1 - p, WelchTest.greater(10, 1.0, 0.04, 10, 1.2, 0.04), P_TOL);
    }

    @Test
    void meanIntervalMatchesScipy() {
        // stats.t.interval(0.95, 9, loc=2.0, scale=0.5/sqrt(10)) = (1.6423215470237138, 2.357678452976286)
        Interval iv = WelchTest.meanInterval(10, 2.0, 0.5, 0.95);
        assertEquals(1.6423215470237138, iv.lower(), P_TOL);
        assertEquals(2.357678452976286, iv.upper(), P_TOL);
    }
}
