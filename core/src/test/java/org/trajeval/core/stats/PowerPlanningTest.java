package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * References: SciPy 1.17.1, {@code (t.isf(alpha/2, n-1) + t.isf(1-power, n-1)) * sd / sqrt(n)}, and
 * the smallest n by a linear search over that expression; beside it statsmodels'
 * 0.15.0 {@code TTestPower().solve_power(effect_size=delta/sd, alpha, power, alternative="two-sided")}
 * (noncentral t, exact) to show how far the approximation is from the exact power.
 */
class PowerPlanningTest {
    private static final double REL_TOL = 1e-12;

    @Test
    void minimumDetectableDifferenceMatchesScipy() {
        assertRel(0.9947137350096734, PowerPlanning.minimumDetectableDifference(1.0, 10, 0.95, 0.8));
        assertRel(0.014179627457521814, PowerPlanning.minimumDetectableDifference(0.0123, 8, 0.95, 0.8));
        assertRel(1.3741266598311743, PowerPlanning.minimumDetectableDifference(2.5, 30, 0.9, 0.9));
        assertRel(0.19915785043122966, PowerPlanning.minimumDetectableDifference(0.02, 2, 0.95, 0.8));
    }

    @Test
    void sequencesNeededMatchScipyAndAreWithinOneOfTheExactNoncentralT() {
        // statsmodels exact n: 33.37, 13.92, 54.91, 3.14 (rounded up: 34, 14, 55, 4)
        assertEquals(34, PowerPlanning.sequencesNeeded(1.0, 0.5, 0.95, 0.8));
        assertEquals(14, PowerPlanning.sequencesNeeded(0.0123, -0.01, 0.95, 0.8));
        assertEquals(56, PowerPlanning.sequencesNeeded(2.5, 1.0, 0.9, 0.9));
        assertEquals(4, PowerPlanning.sequencesNeeded(1.0, 3.0, 0.95, 0.8));
    }

    @Test
    void aDifferenceBelowReachIsReportedAsUnreachable() {
        assertEquals(-1, PowerPlanning.sequencesNeeded(1.0, 1e-6, 0.95, 0.8));
        assertTrue(PowerPlanning.minimumDetectableDifference(0.0, 5, 0.95, 0.8) == 0.0);
    }

    @Test
    void refusesBadPowerAndTooFewSequences() {
        assertThrows(IllegalArgumentException.class, () -> PowerPlanning.minimumDetectableDifference(1, 1, 0.95, 0.8));
        assertThrows(IllegalArgumentException.class, () -> PowerPlanning.minimumDetectableDifference(1, 5, 0.95, 0.4));
        assertThrows(IllegalArgumentException.class, () -> PowerPlanning.sequencesNeeded(1, 0.0, 0.95, 0.8));
    }

    private static void assertRel(double expected, double actual) {
        assertEquals(expected, actual, REL_TOL * Math.abs(expected));
    }
}
