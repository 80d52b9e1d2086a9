package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import org.junit.jupiter.api.Test;

class HolmTest {
    private static final double TIGHT = 1e-15;

    @Test
    void stepDownAdjustmentMatchesStatsmodels() {
        // statsmodels 0.15.0 multipletests(p, method="holm")[1], run by hand:
        // [0.01, 0.04, 0.03] -> [0.03, 0.06, 0.06] (also by hand: 3*0.01, max(0.03, 2*0.03), max(0.06, 1*0.04))
        assertArrayEquals(new double[] {0.03, 0.06, 0.06}, Holm.adjust(new double[] {0.01, 0.04, 0.03}), TIGHT);
        assertArrayEquals(new double[] {0.4, 0.006, 0.16, 0.16, 0.5, 0.05499999999999999},
                Holm.adjust(new double[] {0.2, 0.001, 0.04, 0.04, 0.5, 0.011}), TIGHT);
    }

    @Test
    void adjustedValuesAreCappedAtOneAndTiesStayTied() {
        assertArrayEquals(new double[] {1.0, 1.0}, Holm.adjust(new double[] {1.0, 1.0}), 0.0);
        // three exact Wilcoxon p = 2/2^8 of n = 8: each 3 * 0.0078125 (statsmodels: 0.0234375 thrice)
        assertArrayEquals(new double[] {0.0234375, 0.0234375, 0.0234375},
                Holm.adjust(new double[] {0.0078125, 0.0078125, 0.0078125}), TIGHT);
    }

    @Test
    void aSingleTestIsLeftAlone() {
        assertArrayEquals(new double[] {0.0371}, Holm.adjust(new double[] {0.0371}), 0.0);
    }
}
