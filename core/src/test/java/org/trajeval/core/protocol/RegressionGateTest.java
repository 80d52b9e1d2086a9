package org.trajeval.core.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.trajeval.core.protocol.RegressionGate.Finding;
import org.trajeval.core.protocol.RegressionGate.Verdict;
import org.trajeval.core.report.SuiteReport.RunEntry;

class RegressionGateTest {
    private static final String ATE = "ate_trans_rmse_m";
    private static final double TOL_M = 1e-12;
    private static final RegressionGate.Settings C95 = new RegressionGate.Settings(0.95, 1, 1000);
    private static final List<String> SEQS = List.of("s1", "s2", "s3", "s4", "s5", "s6", "s7", "s8");

    private static List<RunEntry> runs(String method, double[] atePerSeq, double score) {
        List<RunEntry> out = new ArrayList<>();
        for (int i = 0; i < SEQS.size(); i++) {
            for (long seed = 1; seed <= 2; seed++) {
                out.add(new RunEntry(method, SEQS.get(i), seed, "test", null, "ok", null, 1.0,
                        Map.of(ATE, atePerSeq[i]), score, null));
            }
        }
        return out;
    }

    private static double[] plus(double[] a, double d) {
        double[] out = a.clone();
        for (int i = 0; i < out.length; i++) {
            out[i] += d;
        }
        return out;
    }

    private static final double[] BASE = {0.9, 1.0, 1.1, 1.0, 0.95, 1.05, 1.0, 1.0}; // mean 1.0 m

    @Test
    void aConstantWorseningBeyondTheToleranceIsARegression() {
        // every sequence 0.10 m worse: each d_s = 0.10, so the bootstrap interval is [0.10, 0.10];
        // margin = 5 % of the baseline mean 1.0 m = 0.05 m < 0.10 m
        Finding f = RegressionGate.gate("m", runs("m", BASE, 50), runs("m", plus(BASE, 0.10), 50), SEQS, ATE, 0.05,
                C95, 0);
        assertEquals(8, f.n());
        assertEquals(1.0, f.baselineMean(), TOL_M);
        assertEquals(0.05, f.margin(), TOL_M);
        assertEquals(0.10, f.bound(), TOL_M);
        assertEquals(Verdict.REGRESSION, f.verdict());
        assertEquals(0.10, f.relativeChange(), TOL_M);
    }

    @Test
    void aConstantWorseningWithinTheTolerancePasses() {
        // d_s = 0.03 m everywhere: bound 0.03 m < margin 0.05 m
        Finding f = RegressionGate.gate("m", runs("m", BASE, 50), runs("m", plus(BASE, 0.03), 50), SEQS, ATE, 0.05,
                C95, 0);
        assertEquals(0.03, f.bound(), TOL_M);
        assertEquals(Verdict.PASS, f.verdict());
    }

    @Test
    void anImprovementPasses() {
        Finding f = RegressionGate.gate("m", runs("m", BASE, 50), runs("m", plus(BASE, -0.2), 50), SEQS, ATE, 0.0,
                C95, 0);
        assertEquals(Verdict.PASS, f.verdict());
    }

    @Test
    void aLowerScoreIsARegressionBecauseHigherIsBetter() {
        // score 50 -> 40 on every run: d_s = -10, margin 5 % of 50 = 2.5; upper bound -10 < -2.5
        Finding f = RegressionGate.gate("m", runs("m", BASE, 50), runs("m", BASE, 40), SEQS, SuiteAnalysis.SCORE,
                0.05, C95, 0);
        assertEquals(-10.0, f.bound(), TOL_M);
        assertEquals(Verdict.REGRESSION, f.verdict());
    }

    @Test
    void onlyRunsWithTheSameSequenceAndSeedArePaired() {
        List<RunEntry> cand = new ArrayList<>(runs("m", plus(BASE, 0.10), 50));
        cand.removeIf(r -> !r.sequence().equals("s1")); // the candidate ran one sequence only
        Finding f = RegressionGate.gate("m", runs("m", BASE, 50), cand, SEQS, ATE, 0.05, C95, 0);
        assertEquals(1, f.n());
        assertEquals(Verdict.INCONCLUSIVE, f.verdict(), "one paired sequence gives no interval");
    }

    @Test
    void confidenceAtOrBelowOneHalfIsRefused() {
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> new RegressionGate.Settings(0.5, 1, 1000));
    }
}
