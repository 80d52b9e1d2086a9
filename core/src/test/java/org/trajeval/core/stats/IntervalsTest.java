package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.apache.commons.math3.distribution.BinomialDistribution;
import org.apache.commons.math3.distribution.TDistribution;
import org.junit.jupiter.api.Test;

class IntervalsTest {
    /** Newcombe's published values are rounded to 4 decimals. */
    private static final double PUBLISHED_4DP = 5.1e-5;
    private static final double TIGHT = 1e-9;

    @Test
    void sampleStandardDeviationDividesByKMinusOne() {
        // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, sum of squares 32; sd = sqrt(32/7) (population: 2)
        SampleSummary s = SampleSummary.of(new double[] {2, 4, 4, 4, 5, 5, 7, 9});
        assertEquals(5.0, s.mean(), TIGHT);
        assertEquals(Math.sqrt(32.0 / 7.0), s.sd(), TIGHT);
        assertTrue(Double.isNaN(SampleSummary.of(new double[] {3.0}).sd()));
    }

    @Test
    void tIntervalMatchesTheTableValue() {
        // d = 1..5: mean 3, s_d = sqrt(2.5); t_{4,0.975} = 2.776445 (Student t table, 2.776);
        // half width = 2.776445 * sqrt(2.5) / sqrt(5) = 2.776445 * 0.7071068 = 1.963243
        Interval ci = PairedTInterval.of(new double[] {1, 2, 3, 4, 5}, 0.95);
        assertEquals(3.0, ci.estimate(), TIGHT);
        assertEquals(3.0 - 1.963243, ci.lower(), 1e-5);
        assertEquals(3.0 + 1.963243, ci.upper(), 1e-5);
    }

    @Test
    void tIntervalAgreesWithCommonsMathOnRandomSamples() {
        SplittableRandom rng = new SplittableRandom(11);
        for (int trial = 0; trial < 50; trial++) {
            int n = 2 + rng.nextInt(40);
            double[] d = new double[n];
            for (int i = 0; i < n; i++) {
                d[i] = rng.nextGaussian() * 0.3 + 0.1;
            }
            SampleSummary s = SampleSummary.of(d);
            double t = new TDistribution(n - 1).inverseCumulativeProbability(0.95);
            Interval ci = PairedTInterval.of(d, 0.90);
            assertEquals(s.mean() - t * s.sd() / Math.sqrt(n), ci.lower(), 1e-9);
            assertEquals(s.mean() + t * s.sd() / Math.sqrt(n), ci.upper(), 1e-9);
        }
    }

    @Test
    void tIntervalRefusesASingleDifference() {
        assertThrows(IllegalArgumentException.class, () -> PairedTInterval.of(new double[] {1.0}, 0.95));
    }

    @Test
    void wilsonAndClopperPearsonMatchNewcombe1998() {
        // Newcombe, "Two-sided confidence intervals for the single proportion", Stat. Med. 17 (1998),
        // Table II, methods 3 (Wilson score) and 5 (Clopper-Pearson exact), 95 %.
        int[][] cases = {{81, 263}, {15, 148}, {0, 20}, {1, 29}};
        double[][] wilson = {{0.2553, 0.3662}, {0.0624, 0.1605}, {0.0, 0.1611}, {0.0061, 0.1718}};
        double[][] exact = {{0.2527, 0.3676}, {0.0578, 0.1617}, {0.0, 0.1684}, {0.0009, 0.1776}};
        for (int i = 0; i < cases.length; i++) {
            Interval w = BinomialInterval.WILSON.of(cases[i][0], cases[i][1], 0.95);
            Interval c = BinomialInterval.CLOPPER_PEARSON.of(cases[i][0], cases[i][1], 0.95);
            assertEquals(wilson[i][0], w.lower(), PUBLISHED_4DP, "Wilson lower " + i);
            assertEquals(wilson[i][1], w.upper(), PUBLISHED_4DP, "Wilson upper " + i);
            assertEquals(exact[i][0], c.lower(), PUBLISHED_4DP, "Clopper-Pearson lower " + i);
            assertEquals(exact[i][1], c.upper(), PUBLISHED_4DP, "Clopper-Pearson upper " + i);
        }
    }

    @Test
    void clopperPearsonUpperBoundForNoFailuresIsTheClosedForm() {
        // f = 0: upper = 1 - (alpha/2)^(1/n) by hand (P(X = 0) = (1-p)^n = alpha/2)
        Interval c = BinomialInterval.CLOPPER_PEARSON.of(0, 12, 0.95);
        assertEquals(1.0 - Math.pow(0.025, 1.0 / 12), c.upper(), 1e-9);
        assertEquals(0.0, c.lower(), 0.0);
    }

    @Test
    void clopperPearsonBoundsHaveTailProbabilityAlphaOverTwo() {
        // Definition: P(X >= f | p_lo) = alpha/2 and P(X <= f | p_hi) = alpha/2 (Commons Math binomial)
        for (int n = 3; n <= 40; n += 7) {
            for (int f = 1; f < n; f += 2) {
                Interval c = BinomialInterval.CLOPPER_PEARSON.of(f, n, 0.9);
                assertEquals(0.05, 1.0 - new BinomialDistribution(n, c.lower()).cumulativeProbability(f - 1), 1e-7);
                assertEquals(0.05, new BinomialDistribution(n, c.upper()).cumulativeProbability(f), 1e-7);
            }
        }
    }

    @Test
    void bootstrapIsSeededAndBracketsTheMean() {
        double[] d = {0.12, -0.03, 0.2, 0.07, 0.15, 0.01, 0.09};
        Interval a = BootstrapInterval.ofMean(d, 0.95, 2000, 42);
        Interval b = BootstrapInterval.ofMean(d, 0.95, 2000, 42);
        assertEquals(a, b);
        assertTrue(a.lower() < a.estimate() && a.estimate() < a.upper());
        // a resample mean can never leave [min, max] of the values
        assertTrue(a.lower() >= -0.03 && a.upper() <= 0.2);
    }

    @Test
    void bootstrapOfIdenticalValuesIsThatValue() {
        Interval a = BootstrapInterval.ofMean(new double[] {0.5, 0.5, 0.5}, 0.95, 500, 1);
        assertEquals(0.5, a.lower(), TIGHT);
        assertEquals(0.5, a.upper(), TIGHT);
    }
}
