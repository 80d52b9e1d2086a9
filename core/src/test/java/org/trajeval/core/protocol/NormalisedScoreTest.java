package org.trajeval.core.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The lesson's Proposition 3 as seeded property checks. */
class NormalisedScoreTest {
    private static final double SCORE_TOL = 1e-9;

    private static NormalisedScore random(SplittableRandom rng, int q) {
        double[] w = new double[q];
        double sum = 0;
        for (int j = 0; j < q; j++) {
            w[j] = rng.nextDouble() < 0.2 ? 0.0 : rng.nextDouble();
            sum += w[j];
        }
        if (sum == 0) {
            w[0] = 1;
            sum = 1;
        }
        RunMetric[] metrics = RunMetric.values();
        List<NormalisedScore.Term> terms = new java.util.ArrayList<>();
        double acc = 0;
        for (int j = 0; j < q; j++) {
            double wj = j == q - 1 ? 1.0 - acc : w[j] / sum;
            acc += wj;
            terms.add(new NormalisedScore.Term(metrics[j], 0.05 + 3 * rng.nextDouble(), Math.max(0.0, wj)));
        }
        return new NormalisedScore(terms);
    }

    @Test
    void lessonExampleByHand() {
        // caps 2.0 m and 0.8 m, weights 1/2: ATE 0.5 m -> s = 0.75, RPE 0.2 m -> s = 0.75, S = 75
        NormalisedScore s = new NormalisedScore(List.of(new NormalisedScore.Term(RunMetric.ATE_TRANS_RMSE_M, 2.0, 0.5),
                new NormalisedScore.Term(RunMetric.RPE_TRANS_RMSE_M, 0.8, 0.5)));
        assertEquals(75.0, s.score(new double[] {0.5, 0.2}), SCORE_TOL);
        assertEquals(50.0, s.score(new double[] {0.0, 5.0}), SCORE_TOL); // RPE above its cap scores 0
        assertEquals(0.0, s.score(new double[] {Double.NaN, Double.POSITIVE_INFINITY}), SCORE_TOL); // failed run
    }

    @Test
    void scoreIsMonotoneNonIncreasingInEveryMetric() {
        SplittableRandom rng = new SplittableRandom(3);
        for (int trial = 0; trial < 2000; trial++) {
            int q = 1 + rng.nextInt(4);
            NormalisedScore s = random(rng, q);
            double[] m = new double[q];
            for (int j = 0; j < q; j++) {
                m[j] = 4 * rng.nextDouble();
            }
            int j = rng.nextInt(q);
            double[] worse = m.clone();
            worse[j] += 2 * rng.nextDouble();
            double before = s.score(m);
            double after = s.score(worse);
            assertTrue(after <= before + SCORE_TOL, "raising m_" + j + " raised S: " + before + " -> " + after);
            assertTrue(before >= 0 && before <= 100);
        }
    }

    @Test
    void scoreIsLipschitzWithConstantHundredWeightOverCap() {
        SplittableRandom rng = new SplittableRandom(4);
        for (int trial = 0; trial < 2000; trial++) {
            int q = 1 + rng.nextInt(4);
            NormalisedScore s = random(rng, q);
            double[] m = new double[q];
            for (int j = 0; j < q; j++) {
                m[j] = 4 * rng.nextDouble();
            }
            int j = rng.nextInt(q);
            double[] moved = m.clone();
            double delta = (rng.nextDouble() - 0.5) * 3;
            moved[j] = Math.max(0, m[j] + delta);
            NormalisedScore.Term t = s.terms().get(j);
            double bound = 100 * t.weight() / t.cap() * Math.abs(moved[j] - m[j]);
            assertTrue(Math.abs(s.score(moved) - s.score(m)) <= bound + SCORE_TOL);
        }
    }

    @Test
    void slopeInsideTheCapIsExactlyHundredWeightOverCap() {
        // below the cap s_j = 1 - m/c is linear: dS/dm_j = -100 w_j / c_j
        NormalisedScore s = new NormalisedScore(List.of(new NormalisedScore.Term(RunMetric.ATE_TRANS_RMSE_M, 2.0, 0.3),
                new NormalisedScore.Term(RunMetric.RPE_TRANS_RMSE_M, 0.8, 0.7)));
        double slope = (s.score(new double[] {0.6, 0.1}) - s.score(new double[] {0.5, 0.1})) / 0.1;
        assertEquals(-100 * 0.3 / 2.0, slope, 1e-6);
    }

    @Test
    void capsAndWeightsAreChecked() {
        assertThrows(IllegalArgumentException.class, () -> new NormalisedScore.Term(RunMetric.ATE_TRANS_RMSE_M, 0, 1));
        assertThrows(IllegalArgumentException.class, () -> new NormalisedScore.Term(RunMetric.ATE_TRANS_RMSE_M, 1, -0.1));
        assertThrows(IllegalArgumentException.class, () -> new NormalisedScore(List.of(
                new NormalisedScore.Term(RunMetric.ATE_TRANS_RMSE_M, 1, 0.5),
                new NormalisedScore.Term(RunMetric.RPE_TRANS_RMSE_M, 1, 0.4))));
        // within 1e-9 of 1 is accepted
        new NormalisedScore(List.of(new NormalisedScore.Term(RunMetric.ATE_TRANS_RMSE_M, 1, 0.5),
                new NormalisedScore.Term(RunMetric.RPE_TRANS_RMSE_M, 1, 0.5 + 5e-10)));
    }
}
