package org.trajeval.core.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.Comparison;
import org.trajeval.core.report.SuiteReport.RunEntry;

/** The lesson's Proposition 1 and the per-method statistics, on hand-built runs. */
class PairedComparisonTest {
    private static final String ATE = "ate_trans_rmse_m";
    private static final double TIGHT = 1e-12;

    private static RunEntry run(String method, String seq, long seed, Double ate, boolean ok) {
        return new RunEntry(method, seq, seed, "test", "x.csv", ok ? "ok" : "failed",
                ok ? null : new SuiteReport.RunFailure("missing_estimate", "estimate file does not exist"), 1.0,
                new java.util.LinkedHashMap<>(Map.of(ATE, ate == null ? Double.NaN : ate)), ok ? 50.0 : 0.0, null);
    }

    /** m_{a,s} = mu_a + gamma_s + eps_{a,s}, one value per (method, sequence, seed). */
    private static List<RunEntry> model(String method, double mu, double[] gamma, double[][] eps) {
        List<RunEntry> out = new ArrayList<>();
        for (int s = 0; s < gamma.length; s++) {
            for (int k = 0; k < eps[s].length; k++) {
                out.add(run(method, "s" + s, k, mu + gamma[s] + eps[s][k], true));
            }
        }
        return out;
    }

    @Test
    void pairedDifferencesCancelTheSequenceDifficulty() {
        SplittableRandom rng = new SplittableRandom(21);
        int n = 12;
        double[][] e1 = new double[n][3];
        double[][] e2 = new double[n][3];
        double[] gamma = new double[n];
        double[] none = new double[n];
        for (int s = 0; s < n; s++) {
            gamma[s] = 50 * rng.nextDouble(); // strongly varying difficulty
            for (int k = 0; k < 3; k++) {
                e1[s][k] = 0.05 * rng.nextGaussian();
                e2[s][k] = 0.05 * rng.nextGaussian();
            }
        }
        List<String> seqs = new ArrayList<>();
        for (int s = 0; s < n; s++) {
            seqs.add("s" + s);
        }
        SuiteAnalysis.Settings st = SuiteAnalysis.Settings.defaults(5);
        Comparison with = SuiteAnalysis.compare("a", model("a", 1.0, gamma, e1), "b", model("b", 1.2, gamma, e2),
                seqs, ATE, st, 0);
        Comparison without = SuiteAnalysis.compare("a", model("a", 1.0, none, e1), "b", model("b", 1.2, none, e2),
                seqs, ATE, st, 0);
        // d_s = (mu_1 - mu_2) + (eps_1 - eps_2): identical with and without gamma (up to rounding of the sums)
        for (int s = 0; s < n; s++) {
            assertEquals(without.perSequence().get(s).difference(), with.perSequence().get(s).difference(), 1e-9);
        }
        assertEquals(without.tInterval().lower(), with.tInterval().lower(), 1e-9);
        assertEquals(without.tInterval().upper(), with.tInterval().upper(), 1e-9);
        assertTrue(with.tInterval().lower() < -0.2 + 0.1 && with.tInterval().upper() > -0.2 - 0.1);
        // the unpaired spread of method a's sequence means carries Var(gamma), the paired one does not
        double sdPaired = with.tInterval().upper() - with.tInterval().lower();
        assertTrue(sdPaired < 1.0, "paired interval width " + sdPaired);
    }

    @Test
    void comparisonUsesOnlySequencesWhereBothMethodsHaveAValue() {
        List<RunEntry> a = List.of(run("a", "x", 1, 1.0, true), run("a", "y", 1, 2.0, true),
                run("a", "z", 1, null, false));
        List<RunEntry> b = List.of(run("b", "x", 1, 0.5, true), run("b", "y", 1, 1.0, true),
                run("b", "z", 1, 3.0, true));
        Comparison c = SuiteAnalysis.compare("a", a, "b", b, List.of("x", "y", "z"), ATE,
                SuiteAnalysis.Settings.defaults(1), 0);
        assertEquals(2, c.n());
        assertEquals(0.75, c.meanDifference(), TIGHT); // (0.5 + 1.0) / 2
        Comparison score = SuiteAnalysis.compare("a", a, "b", b, List.of("x", "y", "z"), SuiteAnalysis.SCORE,
                SuiteAnalysis.Settings.defaults(1), 1);
        assertEquals(3, score.n()); // failures score 0 and stay in the score comparison
        assertEquals(-50.0 / 3.0, score.meanDifference(), TIGHT);
    }

    @Test
    void singleSequenceGivesNoInterval() {
        Comparison c = SuiteAnalysis.compare("a", List.of(run("a", "x", 1, 1.0, true)), "b",
                List.of(run("b", "x", 1, 0.5, true)), List.of("x"), ATE, SuiteAnalysis.Settings.defaults(1), 0);
        assertEquals(1, c.n());
        assertNull(c.tInterval());
        assertNull(c.bootstrap());
        assertTrue(c.primary().startsWith("none"));
    }

    @Test
    void methodSummaryUsesSampleStandardDeviationAndCountsFailures() {
        // seeds give 1, 2, 3 on x: mean 2, sd (K-1) = 1; a failed run counts in the rate, not in the mean
        List<RunEntry> runs = List.of(run("a", "x", 1, 1.0, true), run("a", "x", 2, 2.0, true),
                run("a", "x", 3, 3.0, true), run("a", "x", 4, null, false));
        SuiteReport.MethodSummary m = SuiteAnalysis.summarise("a", List.of("x"), runs, List.of(ATE), 0.95);
        assertEquals(4, m.runs());
        assertEquals(1, m.failures());
        assertEquals(0.25, m.failureRate().estimate(), TIGHT);
        SuiteReport.SequenceSummary s = m.metrics().get(0).perSequence().get(0);
        assertEquals(3, s.n());
        assertEquals(2.0, s.mean(), TIGHT);
        assertEquals(1.0, s.sd(), TIGHT);
        assertEquals(37.5, m.score().mean(), TIGHT); // (50 + 50 + 50 + 0) / 4
    }
}
