package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class KendallTauTest {
    private static final double TOL = 1e-15;

    @Test
    void withoutTiesTauIsConcordantMinusDiscordantOverAllPairs() {
        // by hand: of the 10 pairs, 6 concordant and 4 discordant: (6 - 4) / 10 = 0.2
        // (SciPy 1.17.1: scipy.stats.kendalltau([1,2,3,4,5], [3,4,1,2,5]).statistic == 0.2)
        assertEquals(0.2, KendallTau.tauB(new double[] {1, 2, 3, 4, 5}, new double[] {3, 4, 1, 2, 5}), TOL);
    }

    @Test
    void tiesAreCorrectedAsTauB() {
        // by hand: x = (1,2,2,3), y = (1,3,2,2): C = 3, D = 1, n0 = 6, one tied pair in x, one in y:
        // tau_b = 2 / sqrt(5 * 5) = 0.4 (SciPy: kendalltau(x, y).statistic == 0.4)
        assertEquals(0.4, KendallTau.tauB(new double[] {1, 2, 2, 3}, new double[] {1, 3, 2, 2}), TOL);
    }

    @Test
    void reversedRankingsGiveMinusOneAndAConstantSampleGivesNaN() {
        assertEquals(-1.0, KendallTau.tauB(new double[] {1, 2, 3}, new double[] {3, 2, 1}), TOL);
        assertTrue(Double.isNaN(KendallTau.tauB(new double[] {1, 2, 3}, new double[] {5, 5, 5})));
    }
}
