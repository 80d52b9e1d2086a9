package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/**
 * References: the Korn-Graubard formulas of {@link ClusteredProportion} computed with numpy and
 * SciPy 1.17.1 by hand ({@code beta.ppf(q, x, n-x+1)}, {@code beta.isf(q, x+1, n-x)},
 * {@code t.isf(q, df)}; Boost's Beta inverse, accurate to a few ulps), values pasted below.
 */
class ClusteredProportionTest {
    private static final double REL_TOL = 1e-12;

    @Test
    void oneFailureAmongEightSequencesOfFiveSeeds() {
        ClusteredProportion.Result r = ClusteredProportion.of(new int[] {0, 0, 0, 0, 0, 1, 0, 0}, fives(8), 0.95);
        assertEquals(8, r.sequences());
        assertRel(1.0256410256410255, r.designEffect());
        assertRel(28.536412751686807, r.effectiveTrials());
        assertRel(0.00017435298935001802, r.interval().lower());
        assertRel(0.16456457839157465, r.interval().upper());
        // wider than the unclustered Clopper-Pearson [0.000633, 0.132] of 1/40
        assertTrue(r.interval().upper() > BinomialInterval.CLOPPER_PEARSON.of(1, 40, 0.95).upper());
    }

    @Test
    void workedExampleOfTwoSequencesIsVeryWide() {
        // one failure on one of two sequences of 10 seeds: v = 2 (0.5^2 + 0.5^2)/400, n* = 0.0475/0.0025 = 19,
        // then (t_{19}/t_{1})^2 = (2.093/12.71)^2 shrinks it to 0.52 effective trials
        ClusteredProportion.Result r = ClusteredProportion.of(new int[] {1, 0}, new int[] {10, 10}, 0.95);
        assertRel(20.0 / 19.0, r.designEffect());
        assertRel(0.5155494671474099, r.effectiveTrials());
        assertRel(3.907355886952273e-63, r.interval().lower());
        assertRel(0.9994807623639959, r.interval().upper());
    }

    @Test
    void noFailureAndAllFailedUseAllRunsCorrectedForTheSequenceCount() {
        ClusteredProportion.Result none = ClusteredProportion.of(new int[8], fives(8), 0.95);
        assertRel(29.268115642755703, none.effectiveTrials());
        assertEquals(0.0, none.interval().lower(), 0.0);
        assertRel(0.11841819293601907, none.interval().upper());
        int[] all = fives(8);
        ClusteredProportion.Result failed = ClusteredProportion.of(all, fives(8), 0.95);
        assertRel(0.8815818070639809, failed.interval().lower());
        assertEquals(1.0, failed.interval().upper(), 0.0);
    }

    @Test
    void clusteredFailuresInflateTheDesignEffect() {
        ClusteredProportion.Result r = ClusteredProportion.of(new int[] {3, 0, 1, 5, 0, 0, 2, 0, 0, 4},
                new int[] {5, 5, 5, 5, 4, 5, 5, 5, 5, 5}, 0.9);
        assertRel(3.380463296429683, r.designEffect());
        assertRel(12.134549298878113, r.effectiveTrials());
        assertRel(0.10621635419268122, r.interval().lower());
        assertRel(0.5814363706695114, r.interval().upper());
        // the same rate in every sequence: no extra variance, design effect 1
        ClusteredProportion.Result even = ClusteredProportion.of(new int[] {2, 2, 2, 2}, new int[] {4, 4, 4, 4}, 0.95);
        assertRel(1.0, even.designEffect());
        assertRel(7.177082299671454, even.effectiveTrials());
        assertRel(0.14225539318744296, even.interval().lower());
        assertRel(0.857744606812557, even.interval().upper());
    }

    @Test
    void oneSequenceSaysNothingAboutClustering() {
        ClusteredProportion.Result r = ClusteredProportion.of(new int[] {1, 0}, new int[] {5, 0}, 0.95);
        assertEquals(1, r.sequences());
        assertEquals(0.0, r.interval().lower(), 0.0);
        assertEquals(1.0, r.interval().upper(), 0.0);
        assertTrue(Double.isNaN(r.designEffect()));
    }

    private static int[] fives(int g) {
        int[] n = new int[g];
        java.util.Arrays.fill(n, 5);
        return n;
    }

    private static void assertRel(double expected, double actual) {
        assertEquals(expected, actual, REL_TOL * Math.abs(expected));
    }
}
