package org.trajeval.core.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.trajeval.core.protocol.SimRealFixtures.byMethod;
import static org.trajeval.core.protocol.SimRealFixtures.ok;
import static org.trajeval.core.protocol.SimRealFixtures.seq;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.trajeval.core.report.DomainGapReport;
import org.trajeval.core.report.SuiteReport.RunEntry;

class DomainGapTest {
    private static final double TOL = 1e-12;
    private static final SuiteAnalysis.Settings STATS = SuiteAnalysis.Settings.defaults(7);
    private static final List<String> ATE = List.of("ate_trans_rmse_m");

    /** A: sim 0.1, 0.3 real 0.9, 1.1; B: sim 0.4, 0.6 real 0.5, 0.7 (m), on scenarios c1, c2. */
    private static List<RunEntry> twoScenarioRuns() {
        return List.of(ok("A", "c1_sim", 1, 0.1), ok("A", "c1_real", 1, 0.9), ok("A", "c2_sim", 1, 0.3),
                ok("A", "c2_real", 1, 1.1), ok("B", "c1_sim", 1, 0.4), ok("B", "c1_real", 1, 0.5),
                ok("B", "c2_sim", 1, 0.6), ok("B", "c2_real", 1, 0.7));
    }

    private static List<SequenceSpec> twoScenarios(boolean withScenario) {
        return List.of(seq("c1_sim", "sim", withScenario ? "c1" : null, Map.of()),
                seq("c1_real", "real", withScenario ? "c1" : null, Map.of()),
                seq("c2_sim", "sim", withScenario ? "c2" : null, Map.of()),
                seq("c2_real", "real", withScenario ? "c2" : null, Map.of()));
    }

    @Test
    void gapIsRealLossMinusSimLossAndTheOrderFlipIsFound() {
        DomainGapReport g = DomainGap.compute(twoScenarios(true), byMethod(twoScenarioRuns()), ATE, STATS);
        assertEquals(DomainGap.PAIRED, g.intervalMethod());
        assertEquals(List.of("c1", "c2"), g.pairedScenarios());
        DomainGapReport.MetricGap m = g.metrics().get(0);
        DomainGapReport.MethodGap a = m.methods().get(0);
        // by hand: L_sim(A) = (0.1 + 0.3)/2 = 0.2, L_real(A) = (0.9 + 1.1)/2 = 1.0, gap 0.8
        assertEquals(0.2, a.lSim(), TOL);
        assertEquals(1.0, a.lReal(), TOL);
        assertEquals(0.8, a.gap(), TOL);
        // each scenario's own gap is 0.8 (0.9 - 0.1, 1.1 - 0.3): every scenario resample gives 0.8
        assertEquals(0.8, a.gapInterval().lower(), TOL);
        assertEquals(0.8, a.gapInterval().upper(), TOL);
        DomainGapReport.MethodGap b = m.methods().get(1);
        // L_sim(B) = 0.5, L_real(B) = 0.6: gap 0.1
        assertEquals(0.1, b.gap(), TOL);
        // A is best in sim (0.2 < 0.5), B in real (0.6 < 1.0): ranks swap, tau_b = -1
        assertEquals(1.0, a.rankSim(), 0.0);
        assertEquals(2.0, a.rankReal(), 0.0);
        assertEquals(-1.0, m.kendallTau(), TOL);
        assertEquals(1, m.flips().size());
        DomainGapReport.Flip f = m.flips().get(0);
        assertEquals("A", f.betterInSim());
        assertEquals("B", f.betterInReal());
        assertEquals(0.7, f.gapDifference(), TOL);
        assertEquals(0.7, f.gapDifferenceInterval().lower(), TOL);
        // two paired sequences per side: the comparison is descriptive only, so the flip is not supported
        assertEquals("bootstrap_descriptive", f.sim().test());
        assertFalse(f.supported());
    }

    @Test
    void withoutScenariosEachDomainIsResampledOnItsOwn() {
        DomainGapReport g = DomainGap.compute(twoScenarios(false), byMethod(twoScenarioRuns()), ATE, STATS);
        assertEquals(DomainGap.INDEPENDENT, g.intervalMethod());
        DomainGapReport.MethodGap a = g.metrics().get(0).methods().get(0);
        // by hand: resampled sim means 0.1, 0.2, 0.3 (p 1/4, 1/2, 1/4), real 0.9, 1.0, 1.1 likewise; the gap is
        // 0.6 and 1.0 each with p 1/16 = 6.25 % > 2.5 %, so the 95 % percentile interval is [0.6, 1.0]
        assertEquals(0.6, a.gapInterval().lower(), TOL);
        assertEquals(1.0, a.gapInterval().upper(), TOL);
    }

    @Test
    void anUnpairedSimSequenceIsResampledWithinItsDomainBesideTheScenarios() {
        List<SequenceSpec> seqs = new ArrayList<>(twoScenarios(true));
        seqs.add(seq("x_sim", "sim", null, Map.of()));
        List<RunEntry> runs = new ArrayList<>(twoScenarioRuns());
        runs.add(ok("A", "x_sim", 1, 0.2));
        runs.add(ok("B", "x_sim", 1, 0.5));
        DomainGapReport g = DomainGap.compute(seqs, byMethod(runs), ATE, STATS);
        assertEquals(DomainGap.PARTLY, g.intervalMethod());
        // by hand: L_sim(A) = (0.1 + 0.3 + 0.2) / 3 = 0.2, unchanged; gap still 0.8, but the lone sim sequence
        // now varies it: a resample drawing c1 twice gives L_sim = (0.1 + 0.1 + 0.2) / 3, gap 0.9 - 0.1333 = 0.7667
        DomainGapReport.MethodGap a = g.metrics().get(0).methods().get(0);
        assertEquals(0.8, a.gap(), TOL);
        assertEquals(3, a.nSim());
        assertTrue(a.gapInterval().lower() <= 0.8 && a.gapInterval().upper() >= 0.8);
    }

    @Test
    void aFlipFoundOnSixScenariosOnBothSidesIsSupported() {
        List<SequenceSpec> seqs = new ArrayList<>();
        List<RunEntry> runs = new ArrayList<>();
        for (int c = 0; c < 6; c++) {
            seqs.add(seq("s" + c, "sim", "c" + c, Map.of()));
            seqs.add(seq("r" + c, "real", "c" + c, Map.of()));
            // A better than B in sim on every scenario, worse in real on every one (differences all non-zero)
            runs.add(ok("A", "s" + c, 1, 0.10 + 0.01 * c));
            runs.add(ok("A", "r" + c, 1, 0.50 + 0.02 * c));
            runs.add(ok("B", "s" + c, 1, 0.20 + 0.015 * c));
            runs.add(ok("B", "r" + c, 1, 0.30 + 0.01 * c));
        }
        DomainGapReport.Flip f = DomainGap.compute(seqs, byMethod(runs), ATE, STATS).metrics().get(0).flips().get(0);
        // six differences of one sign: exact Wilcoxon two-sided p = 2 / 2^6 = 0.03125 < 0.05 on each side
        assertEquals("wilcoxon_exact", f.sim().test());
        assertEquals(0.03125, f.sim().wilcoxonP(), TOL);
        assertEquals(0.03125, f.real().wilcoxonP(), TOL);
        assertTrue(f.sim().supports());
        assertTrue(f.real().supports());
        assertTrue(f.supported());
    }

    @Test
    void simulationOnlyGivesAWarningAndNoSectionRealOnlyNeither() {
        List<SequenceSpec> sim = List.of(seq("a", "sim", null, Map.of()), seq("b", null, null, Map.of()));
        assertNull(DomainGap.compute(sim, byMethod(List.of(ok("A", "a", 1, 0.1))), ATE, STATS));
        assertNotNull(DomainGap.simOnlyWarning(sim));
        List<SequenceSpec> real = List.of(seq("a", "real", null, Map.of()));
        assertNull(DomainGap.simOnlyWarning(real));
        assertNull(DomainGap.compute(real, byMethod(List.of(ok("A", "a", 1, 0.1))), ATE, STATS));
    }

    @Test
    void ranksAreMidRanksBestFirst() {
        // losses 0.3, 0.1, 0.3: best 0.1 rank 1, the two 0.3 share ranks 2 and 3: 2.5; the score ranks high first
        assertEquals(List.of(2.5, 1.0, 2.5), toList(DomainGap.ranks(new double[] {0.3, 0.1, 0.3}, false)));
        assertEquals(List.of(1.5, 3.0, 1.5), toList(DomainGap.ranks(new double[] {0.3, 0.1, 0.3}, true)));
    }

    private static List<Double> toList(double[] v) {
        return java.util.Arrays.stream(v).boxed().toList();
    }
}
