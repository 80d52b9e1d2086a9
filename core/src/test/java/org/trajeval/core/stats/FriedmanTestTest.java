package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/**
 * References: SciPy 1.17.1 {@code stats.friedmanchisquare(*columns)} for chi2_F and its p, {@code
 * stats.f.sf(F, k-1, (k-1)(n-1))} for Iman-Davenport with F = (n-1) chi2 / (n(k-1) - chi2), and
 * the mean of {@code stats.rankdata(row)} for the average ranks; run by hand, values pasted below.
 */
class FriedmanTestTest {
    /** SciPy's own rounding in its sums: the references carry about 14 correct digits. */
    private static final double REL_TOL = 1e-12;

    @Test
    void errorsWithTiesMatchScipy() {
        double[][] v = {{0.10, 0.20, 0.30}, {0.12, 0.25, 0.22}, {0.11, 0.21, 0.35}, {0.15, 0.15, 0.40},
            {0.09, 0.30, 0.29}, {0.13, 0.13, 0.13}, {0.20, 0.18, 0.50}};
        FriedmanTest.Result r = FriedmanTest.of(v, true);
        assertRel(6.347826086956514, r.chiSquare());
        assertRel(0.04183955715720695, r.chiSquareP());
        assertRel(4.977272727272716, r.imanDavenport());
        assertRel(0.02666495018694773, r.imanDavenportP());
        assertArrayEquals(new double[] {1.3571428571428572, 2.0714285714285716, 2.5714285714285716},
                r.averageRanks(), 1e-15);
        assertEquals(2, r.df());
        assertEquals(12, r.dfDenominator());
    }

    @Test
    void scoresRankHighestFirst() {
        // the same data negated and ranked as scores gives the same statistics
        double[][] v = {{1, 2, 3, 4}, {2, 1, 3, 4}, {1, 3, 2, 4}, {1, 2, 4, 3}, {1, 2, 3, 4}, {2, 1, 4, 3},
            {1, 2, 3, 4}, {1, 3, 2, 4}, {1, 2, 3, 4}, {3, 1, 2, 4}};
        double[][] scores = new double[v.length][];
        for (int i = 0; i < v.length; i++) {
            scores[i] = java.util.Arrays.stream(v[i]).map(x -> -x).toArray();
        }
        for (FriedmanTest.Result r : new FriedmanTest.Result[] {FriedmanTest.of(v, true),
            FriedmanTest.of(scores, false)}) {
            assertRel(20.519999999999982, r.chiSquare());
            assertRel(0.000132423523358252, r.chiSquareP());
            assertRel(19.481012658227794, r.imanDavenport());
            assertRel(6.301821638410037e-07, r.imanDavenportP());
            assertArrayEquals(new double[] {1.4, 1.9, 2.9, 3.8}, r.averageRanks(), 1e-15);
        }
    }

    @Test
    void allEqualMethodsGiveNoEvidence() {
        // every block tied throughout: C = 0, chi2_F = 0 by convention (SciPy returns nan), p = 1
        FriedmanTest.Result r = FriedmanTest.of(new double[][] {{1, 1, 1}, {2, 2, 2}, {5, 5, 5}}, true);
        assertEquals(0.0, r.chiSquare(), 0.0);
        assertEquals(1.0, r.chiSquareP(), 0.0);
        assertEquals(1.0, r.imanDavenportP(), 0.0);
        assertArrayEquals(new double[] {2, 2, 2}, r.averageRanks(), 0.0);
    }

    @Test
    void perfectAgreementMakesTheImanDavenportStatisticInfinite() {
        // n = 2 blocks ranking 3 methods identically: chi2_F = n(k-1) = 4 by hand, F infinite, p_F = 0;
        // P(chi2_2 > 4) = exp(-2) = 0.1353352832366127 by hand
        FriedmanTest.Result r = FriedmanTest.of(new double[][] {{1, 2, 3}, {4, 5, 6}}, true);
        assertRel(4.0, r.chiSquare());
        assertRel(Math.exp(-2.0), r.chiSquareP());
        assertEquals(Double.POSITIVE_INFINITY, r.imanDavenport());
        assertEquals(0.0, r.imanDavenportP(), 0.0);
    }

    @Test
    void refusesFewerThanTwoBlocksOrThreeMethods() {
        assertThrows(IllegalArgumentException.class, () -> FriedmanTest.of(new double[][] {{1, 2, 3}}, true));
        assertThrows(IllegalArgumentException.class, () -> FriedmanTest.of(new double[][] {{1, 2}, {2, 1}}, true));
    }

    private static void assertRel(double expected, double actual) {
        assertEquals(expected, actual, REL_TOL * Math.abs(expected));
    }
}
