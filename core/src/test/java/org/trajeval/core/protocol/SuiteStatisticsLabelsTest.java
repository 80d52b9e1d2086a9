package org.trajeval.core.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.Comparison;
import org.trajeval.core.report.SuiteReport.RunEntry;
import org.trajeval.core.stats.ClusteredProportion;
import org.trajeval.core.stats.Holm;

/**
 * Every comparison says what it used (n, non-zero differences, test and variant), and the
 * many-methods machinery (Holm families, Friedman, rank groups) handles zeros, ties, n = 1 and 2,
 * all-equal and all-failed methods.
 */
class SuiteStatisticsLabelsTest {
    private static final String ATE = "ate_trans_rmse_m";
    private static final double TIGHT = 1e-12;

    private static RunEntry run(String method, String seq, long seed, Double ate) {
        boolean ok = ate != null;
        Map<String, Double> m = new LinkedHashMap<>();
        m.put(ATE, ate);
        return new RunEntry(method, seq, seed, "test", "x.csv", ok ? "ok" : "failed",
                ok ? null : new SuiteReport.RunFailure("diverged", "diverged"), 1.0, ok ? m : null,
                ok ? 100.0 * (1.0 - ate) : 0.0, null);
    }

    /** One seed per sequence; value i of {@code ate} on sequence s{i} (null: failed). */
    private static List<RunEntry> runs(String method, Double... ate) {
        List<RunEntry> out = new ArrayList<>();
        for (int i = 0; i < ate.length; i++) {
            out.add(run(method, "s" + i, 1, ate[i]));
        }
        return out;
    }

    private static List<String> seqs(int n) {
        List<String> s = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            s.add("s" + i);
        }
        return s;
    }

    private static Comparison compare(List<RunEntry> a, List<RunEntry> b, int n, String key) {
        return SuiteAnalysis.compare("a", a, "b", b, seqs(n), key, SuiteAnalysis.Settings.defaults(3), 0);
    }

    /** n sequences, the first {@code nonzero} with B worse by 0.01 (i+1), the rest equal. */
    private static Comparison withZeros(int n, int nonzero) {
        Double[] a = new Double[n];
        Double[] b = new Double[n];
        for (int i = 0; i < n; i++) {
            a[i] = 0.1 + 0.001 * i;
            b[i] = i < nonzero ? a[i] + 0.01 * (i + 1) : a[i];
        }
        return compare(runs("a", a), runs("b", b), n, ATE);
    }

    @Test
    void manySequencesWithFiftyOrFewerNonZeroDifferencesNameTheExactTest() {
        // the case: 51 or 56 paired sequences, at most 50 non-zero differences -> exact Wilcoxon
        for (int[] c : new int[][] {{51, 50}, {56, 45}}) {
            Comparison k = withZeros(c[0], c[1]);
            assertEquals(c[0], k.n());
            assertEquals(c[1], k.nonzeroDifferences());
            assertEquals("exact", k.wilcoxon().method());
            assertEquals("t_interval", k.test());
            assertTrue(k.primary().contains("Wilcoxon signed-rank (exact, on " + c[1] + " non-zero of " + c[0]),
                    k.primary());
        }
        Comparison big = withZeros(56, 53);
        assertEquals("normal_approximation", big.wilcoxon().method());
        assertTrue(big.primary().contains("normal approximation, on 53 non-zero of 56"), big.primary());
    }

    @Test
    void smallSuitesNameTheTestOfTheirOwnNonZeroCount() {
        Comparison seven = withZeros(8, 7);
        assertEquals("wilcoxon_exact", seven.test());
        assertTrue(seven.primary().contains("on 7 non-zero of 8"), seven.primary());
        Comparison five = withZeros(8, 5);
        assertEquals("bootstrap_descriptive", five.test());
        assertTrue(five.primary().contains("5 non-zero of 8") && five.primary().contains("2/2^5"), five.primary());
    }

    @Test
    void allZeroDifferencesAreLabelledAsSuchNotAsANormalApproximation() {
        Comparison z = withZeros(8, 0);
        assertEquals(0, z.nonzeroDifferences());
        assertEquals("no_nonzero_differences", z.wilcoxon().method());
        assertEquals(1.0, z.wilcoxon().pValue(), 0.0);
        assertEquals("bootstrap_descriptive", z.test());
        assertEquals(0.0, z.hodgesLehmann().estimate(), 0.0);
        assertEquals(8, z.wins().ties());
        assertEquals(0.0, z.wins().shareABetter(), 0.0);
    }

    @Test
    void oneAndTwoSequences() {
        Comparison one = withZeros(1, 1);
        assertEquals("none", one.test());
        assertNull(one.planning());
        assertNotNull(one.hodgesLehmann());
        Comparison two = withZeros(2, 2);
        assertEquals("bootstrap_descriptive", two.test());
        // d = (-0.01, -0.02): s_d = 0.01/sqrt 2; the planning figure exists from n = 2
        assertEquals(0.01 / Math.sqrt(2.0), two.planning().sdDifference(), TIGHT);
        assertEquals(2, two.wins().aBetter()); // lower error: A better on both
    }

    @Test
    void winsCountTheBetterSideOfEachMetric() {
        Comparison score = compare(runs("a", 0.1, 0.5, 0.3), runs("b", 0.2, 0.4, 0.3), 3, SuiteAnalysis.SCORE);
        // scores 90/50/70 vs 80/60/70: A higher on s0, lower on s1, tied on s2
        assertEquals(1, score.wins().aBetter());
        assertEquals(1, score.wins().ties());
        assertEquals(1, score.wins().bBetter());
        assertEquals(1.0 / 3.0, score.wins().shareABetter(), TIGHT);
    }

    @Test
    void targetDifferenceGivesTheSequencesNeeded() {
        SuiteAnalysis.Settings st = new SuiteAnalysis.Settings(3, 0.95, 1000, 0.8, Map.of(ATE, 0.005));
        Comparison c = SuiteAnalysis.compare("a", runs("a", 0.1, 0.2, 0.3, 0.4), "b", runs("b", 0.11, 0.23, 0.31,
                0.45), seqs(4), ATE, st, 0);
        assertEquals(0.005, c.planning().targetDifference(), 0.0);
        assertEquals(org.trajeval.core.stats.PowerPlanning.sequencesNeeded(c.planning().sdDifference(), 0.005,
                0.95, 0.8), c.planning().sequencesNeeded());
    }

    @Test
    void threeMethodsFormOneHolmFamilyPerMetricAndAreRanked() {
        Map<String, List<RunEntry>> r = new LinkedHashMap<>();
        r.put("a", runs("a", 0.10, 0.11, 0.12, 0.13, 0.14, 0.15, 0.16, 0.17));
        r.put("b", runs("b", 0.20, 0.21, 0.22, 0.23, 0.24, 0.25, 0.26, 0.27));
        r.put("c", runs("c", 0.20, 0.22, 0.21, 0.24, 0.23, 0.26, 0.25, 0.28));
        List<String> methods = List.of("a", "b", "c");
        List<Comparison> raw = new ArrayList<>();
        for (String key : List.of(ATE, SuiteAnalysis.SCORE)) {
            raw.add(SuiteAnalysis.compare("a", r.get("a"), "b", r.get("b"), seqs(8), key,
                    SuiteAnalysis.Settings.defaults(1), 0));
            raw.add(SuiteAnalysis.compare("a", r.get("a"), "c", r.get("c"), seqs(8), key,
                    SuiteAnalysis.Settings.defaults(1), 1));
            raw.add(SuiteAnalysis.compare("b", r.get("b"), "c", r.get("c"), seqs(8), key,
                    SuiteAnalysis.Settings.defaults(1), 2));
        }
        MethodRanking.Result res = MethodRanking.of(methods, r, seqs(8), List.of(ATE, SuiteAnalysis.SCORE), raw,
                0.95);
        double[] p = raw.subList(0, 3).stream().mapToDouble(c -> c.wilcoxon().pValue()).toArray();
        double[] adj = Holm.adjust(p);
        for (int i = 0; i < 3; i++) {
            assertEquals(adj[i], res.comparisons().get(i).holm().pAdjusted(), 0.0);
            assertEquals(3, res.comparisons().get(i).holm().m());
            assertTrue(res.comparisons().get(i).holm().family().contains(ATE));
        }
        assertEquals(2, res.rankings().size());
        SuiteReport.Ranking ate = res.rankings().get(0);
        assertEquals(8, ate.n());
        assertEquals(1.0, ate.methods().get(0).averageRank(), 0.0); // a best on every sequence
        // b vs c alternate: b ranks 2,3,2,3,... with one tie (s0: both 0.20 -> 2.5 each)
        assertEquals((2.5 + 2 + 3 + 2 + 3 + 2 + 3 + 2) / 8.0, ate.methods().get(1).averageRank(), TIGHT);
        // a beats b and c on all 8 sequences: Holm p = 3 * 2/2^8 and 2 * 2/2^8 < 0.05, b ~ c: one group {b, c}
        assertEquals(List.of(List.of("b", "c")), ate.groups());
        assertTrue(ate.friedman().pValue() < 0.01);
    }

    @Test
    void allEqualMethodsFormOneGroupWithAFriedmanPOfOne() {
        Map<String, List<RunEntry>> r = new LinkedHashMap<>();
        for (String m : List.of("a", "b", "c")) {
            r.put(m, runs(m, 0.1, 0.2, 0.3, 0.4));
        }
        List<Comparison> raw = List.of(
                SuiteAnalysis.compare("a", r.get("a"), "b", r.get("b"), seqs(4), ATE, SuiteAnalysis.Settings.defaults(1), 0),
                SuiteAnalysis.compare("a", r.get("a"), "c", r.get("c"), seqs(4), ATE, SuiteAnalysis.Settings.defaults(1), 1),
                SuiteAnalysis.compare("b", r.get("b"), "c", r.get("c"), seqs(4), ATE, SuiteAnalysis.Settings.defaults(1), 2));
        SuiteReport.Ranking k = MethodRanking.of(List.of("a", "b", "c"), r, seqs(4), List.of(ATE), raw, 0.95)
                .rankings().get(0);
        assertEquals(0.0, k.friedman().statistic(), 0.0);
        assertEquals(1.0, k.friedman().pValue(), 0.0);
        assertEquals(List.of(List.of("a", "b", "c")), k.groups());
        k.methods().forEach(m -> assertEquals(2.0, m.averageRank(), 0.0));
    }

    @Test
    void anAllFailedMethodLeavesErrorMetricsUnrankedButIsRankedLastOnTheScore() {
        Map<String, List<RunEntry>> r = new LinkedHashMap<>();
        r.put("a", runs("a", 0.1, 0.2, 0.3));
        r.put("b", runs("b", 0.2, 0.3, 0.4));
        r.put("c", runs("c", null, null, null));
        List<Comparison> raw = new ArrayList<>();
        int stream = 0;
        for (String key : List.of(ATE, SuiteAnalysis.SCORE)) {
            for (String[] pair : new String[][] {{"a", "b"}, {"a", "c"}, {"b", "c"}}) {
                raw.add(SuiteAnalysis.compare(pair[0], r.get(pair[0]), pair[1], r.get(pair[1]), seqs(3), key,
                        SuiteAnalysis.Settings.defaults(1), stream++));
            }
        }
        MethodRanking.Result res = MethodRanking.of(List.of("a", "b", "c"), r, seqs(3),
                List.of(ATE, SuiteAnalysis.SCORE), raw, 0.95);
        Comparison ac = res.comparisons().get(1);
        assertEquals(0, ac.n());
        assertEquals("none", ac.test());
        assertNull(ac.holm());
        assertEquals(1, res.comparisons().get(0).holm().m()); // the ATE family holds only a-b
        SuiteReport.Ranking ate = res.rankings().get(0);
        assertEquals(0, ate.n());
        assertNull(ate.friedman());
        assertNull(ate.methods().get(0).averageRank());
        SuiteReport.Ranking score = res.rankings().get(1);
        assertEquals(3, score.n());
        assertEquals(3.0, score.methods().get(2).averageRank(), 0.0);
    }

    @Test
    void failureRateIntervalTreatsSeedsOfASequenceAsACluster() {
        List<RunEntry> runs = new ArrayList<>();
        for (int s = 0; s < 4; s++) {
            for (int k = 0; k < 5; k++) {
                runs.add(run("a", "s" + s, k, s == 2 && k < 3 ? null : 0.1 + 0.01 * k));
            }
        }
        SuiteReport.MethodSummary m = SuiteAnalysis.summarise("a", seqs(4), runs, List.of(ATE), 0.95);
        SuiteReport.ClusteredBounds c = m.failureRate().clustered();
        assertEquals(ClusteredProportion.METHOD, c.method());
        ClusteredProportion.Result direct = ClusteredProportion.of(new int[] {0, 0, 3, 0}, new int[] {5, 5, 5, 5},
                0.95);
        assertEquals(direct.interval().lower(), c.lower(), 0.0);
        assertEquals(direct.interval().upper(), c.upper(), 0.0);
        assertTrue(c.upper() > m.failureRate().clopperPearson().upper(), "clustered interval is wider");
        assertTrue(c.designEffect() > 1.0);
        assertNotNull(m.metrics().get(0).variance());
        assertNotNull(m.scoreVariance());
    }
}
