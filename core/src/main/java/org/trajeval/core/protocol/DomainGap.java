package org.trajeval.core.protocol;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.trajeval.core.report.DomainGapReport;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.Bounds;
import org.trajeval.core.report.SuiteReport.RunEntry;
import org.trajeval.core.stats.ClusterBootstrap;
import org.trajeval.core.stats.Interval;
import org.trajeval.core.stats.KendallTau;
import org.trajeval.core.stats.SampleSummary;

/**
 * The transfer gap of the lesson's section 8, per method and metric:
 * <pre>
 *   m_s      = mean over the method's seeds on sequence s (successful runs; every run for the score)
 *   L_sim    = mean of m_s over the sim sequences with a value,  L_real likewise over the real ones
 *   Delta    = L_real - L_sim                                      (unit of the metric)
 * </pre>
 * Interval: a seeded percentile bootstrap, stratified. With at least two scenarios that have both a sim
 * and a real sequence, those scenarios are one stratum resampled whole, so a scenario's sim and real
 * sequences stay together (paired: {@code paired_over_scenarios} when that is every sequence,
 * {@code partly_paired} otherwise); the other sim sequences and the other real sequences are two
 * more strata resampled one by one ({@code independent_domains} when nothing is paired). The same
 * resamples serve every method, so the difference of two methods' gaps has an
 * interval too. Rankings per domain sort L (1 = best, ties mid-ranked); Kendall's tau_b compares them.
 * A pair of methods flips when their order in sim is the reverse of their order in real; the flip is
 * supported when the paired comparison over each domain's sequences (the suite's own rules, see
 * {@link SuiteAnalysis#compare}) finds that domain's order at the level.
 */
public final class DomainGap {
    /** Interval method: scenarios resampled whole. */
    public static final String PAIRED = "paired_over_scenarios";
    /** Interval method: scenarios with both domains resampled whole, the other sequences within their domain. */
    public static final String PARTLY = "partly_paired";
    /** Interval method: each domain's sequences resampled on their own. */
    public static final String INDEPENDENT = "independent_domains";

    private DomainGap() {
    }

    /**
     * @param sequences the evaluated sequences, in report order
     * @param runsByMethod every method's runs, in manifest order
     * @param keys the compared metrics (score metrics and {@link SuiteAnalysis#SCORE})
     * @param stats seed, level and resamples
     * @return the section, or null unless there are both sim and real sequences
     */
    public static DomainGapReport compute(List<SequenceSpec> sequences, Map<String, List<RunEntry>> runsByMethod,
            List<String> keys, SuiteAnalysis.Settings stats) {
        List<String> ids = sequences.stream().map(SequenceSpec::id).toList();
        List<String> sim = sequences.stream().filter(s -> s.about().sim()).map(SequenceSpec::id).toList();
        List<String> real = sequences.stream().filter(s -> s.about().real()).map(SequenceSpec::id).toList();
        if (sim.isEmpty() || real.isEmpty()) {
            return null;
        }
        Map<String, List<Integer>> byScenario = new LinkedHashMap<>();
        Map<String, boolean[]> sides = new LinkedHashMap<>();
        boolean everyOnePaired = true;
        for (int i = 0; i < sequences.size(); i++) {
            SequenceSpec s = sequences.get(i);
            if (!s.about().sim() && !s.about().real()) {
                continue;
            }
            String c = s.about().scenario();
            if (c == null) {
                everyOnePaired = false;
                continue;
            }
            byScenario.computeIfAbsent(c, k -> new ArrayList<>()).add(i);
            sides.computeIfAbsent(c, k -> new boolean[2])[s.about().sim() ? 0 : 1] = true;
        }
        List<String> paired = new ArrayList<>();
        sides.forEach((c, b) -> {
            if (b[0] && b[1]) {
                paired.add(c);
            }
        });
        everyOnePaired &= paired.size() == sides.size();
        boolean usePaired = paired.size() >= 2;
        String reason;
        List<int[][]> strata = new ArrayList<>();
        List<String> simAlone = new ArrayList<>(sim);
        List<String> realAlone = new ArrayList<>(real);
        String method;
        if (usePaired) {
            strata.add(paired.stream().map(c -> byScenario.get(c).stream().mapToInt(Integer::intValue).toArray())
                    .toArray(int[][]::new));
            for (String c : paired) {
                for (int i : byScenario.get(c)) {
                    simAlone.remove(ids.get(i));
                    realAlone.remove(ids.get(i));
                }
            }
        }
        if (usePaired && everyOnePaired) {
            method = PAIRED;
            reason = "every sim and real sequence belongs to one of " + paired.size()
                    + " scenarios with both domains: scenarios are resampled whole";
        } else if (usePaired) {
            method = PARTLY;
            reason = paired.size() + " scenarios with both domains are resampled whole; the other " + simAlone.size()
                    + " sim and " + realAlone.size() + " real sequences within their domain";
        } else {
            method = INDEPENDENT;
            reason = "fewer than 2 scenarios with both domains: each domain's sequences are resampled on their own";
        }
        if (!simAlone.isEmpty()) {
            strata.add(singletons(ids, simAlone));
        }
        if (!realAlone.isEmpty()) {
            strata.add(singletons(ids, realAlone));
        }
        int[][] plans = ClusterBootstrap.plans(ids.size(), strata.toArray(new int[0][][]), stats.resamples(),
                stats.seed() * 1_000_003L + 0x5eed);
        boolean[] isSim = new boolean[ids.size()];
        boolean[] isReal = new boolean[ids.size()];
        for (int i = 0; i < ids.size(); i++) {
            isSim[i] = sim.contains(ids.get(i));
            isReal[i] = real.contains(ids.get(i));
        }
        List<String> methods = new ArrayList<>(runsByMethod.keySet());
        List<DomainGapReport.MetricGap> out = new ArrayList<>();
        int stream = 0;
        for (String key : keys) {
            boolean higher = SuiteAnalysis.SCORE.equals(key);
            double[][] m = new double[methods.size()][];
            double[] lSim = new double[methods.size()];
            double[] lReal = new double[methods.size()];
            double[][] reps = new double[methods.size()][];
            for (int a = 0; a < methods.size(); a++) {
                m[a] = sequenceMeans(runsByMethod.get(methods.get(a)), ids, key);
                lSim[a] = weightedMean(m[a], isSim, null);
                lReal[a] = weightedMean(m[a], isReal, null);
                reps[a] = new double[plans.length];
                for (int b = 0; b < plans.length; b++) {
                    reps[a][b] = weightedMean(m[a], isReal, plans[b]) - weightedMean(m[a], isSim, plans[b]);
                }
            }
            double[] rankSim = ranks(lSim, higher);
            double[] rankReal = ranks(lReal, higher);
            List<DomainGapReport.MethodGap> gaps = new ArrayList<>();
            List<Double> tx = new ArrayList<>();
            List<Double> ty = new ArrayList<>();
            for (int a = 0; a < methods.size(); a++) {
                double gap = lReal[a] - lSim[a];
                Interval gi = Double.isFinite(gap) ? org.trajeval.core.stats.BootstrapInterval.percentile(gap,
                        reps[a], stats.level()) : null;
                gaps.add(new DomainGapReport.MethodGap(methods.get(a), count(m[a], isSim), count(m[a], isReal),
                        SuiteAnalysis.nullable(lSim[a]), SuiteAnalysis.nullable(lReal[a]), SuiteAnalysis.nullable(gap),
                        gi == null ? null : new Bounds(gi.lower(), gi.upper()), SuiteAnalysis.nullable(rankSim[a]),
                        SuiteAnalysis.nullable(rankReal[a])));
                if (Double.isFinite(rankSim[a]) && Double.isFinite(rankReal[a])) {
                    tx.add(rankSim[a]);
                    ty.add(rankReal[a]);
                }
            }
            double tau = KendallTau.tauB(tx.stream().mapToDouble(Double::doubleValue).toArray(),
                    ty.stream().mapToDouble(Double::doubleValue).toArray());
            List<DomainGapReport.Flip> flips = new ArrayList<>();
            for (int a = 0; a < methods.size(); a++) {
                for (int b = a + 1; b < methods.size(); b++) {
                    int sSim = (int) Math.signum(lSim[a] - lSim[b]);
                    int sReal = (int) Math.signum(lReal[a] - lReal[b]);
                    if (sSim * sReal >= 0) {
                        continue;
                    }
                    double diff = (lReal[a] - lSim[a]) - (lReal[b] - lSim[b]);
                    double[] dr = new double[plans.length];
                    for (int k = 0; k < plans.length; k++) {
                        dr[k] = reps[a][k] - reps[b][k];
                    }
                    Interval di = org.trajeval.core.stats.BootstrapInterval.percentile(diff, dr, stats.level());
                    String na = methods.get(a);
                    String nb = methods.get(b);
                    // A better in a domain: A - B below zero for a loss, above zero for the score
                    String betterSim = (sSim < 0) != higher ? na : nb;
                    String betterReal = (sReal < 0) != higher ? na : nb;
                    DomainGapReport.Side simSide = side(na, nb, runsByMethod, sim, key, stats, stream++, sSim);
                    DomainGapReport.Side realSide = side(na, nb, runsByMethod, real, key, stats, stream++, sReal);
                    flips.add(new DomainGapReport.Flip(na, nb, betterSim, betterReal, diff,
                            di == null ? null : new Bounds(di.lower(), di.upper()), simSide, realSide,
                            simSide.supports() && realSide.supports()));
                }
            }
            out.add(new DomainGapReport.MetricGap(key, higher ? "higher" : "lower", gaps,
                    SuiteAnalysis.nullable(tau), flips));
        }
        return new DomainGapReport(sim, real, usePaired ? paired : List.of(), method, reason, stats.level(),
                stats.resamples(), out);
    }

    /**
     * @return a warning when the evaluated sequences include sim ones but no real one (lesson section 8:
     *     "report both results side-by-side, not simulation alone"), else null
     */
    public static String simOnlyWarning(List<SequenceSpec> sequences) {
        boolean sim = sequences.stream().anyMatch(s -> s.about().sim());
        boolean real = sequences.stream().anyMatch(s -> s.about().real());
        return sim && !real ? "DOMAIN: every evaluated sequence with a domain is simulated: real-world validation is "
                + "missing (lesson section 8: validate on real logs and report both side by side)" : null;
    }

    /** The paired comparison A - B over one domain's sequences, and whether it finds the order {@code sign}. */
    private static DomainGapReport.Side side(String a, String b, Map<String, List<RunEntry>> runs, List<String> seqs,
            String key, SuiteAnalysis.Settings stats, int stream, int sign) {
        SuiteReport.Comparison c = SuiteAnalysis.compare(a, runs.get(a), b, runs.get(b), seqs, key, stats,
                1_000 + stream);
        Double p = c.wilcoxon() == null ? null : c.wilcoxon().pValue();
        return new DomainGapReport.Side(c.n(), c.meanDifference(), c.bootstrap(), p, c.test(),
                supports(c, sign, 1.0 - stats.level()));
    }

    /**
     * A domain supports an order (sign of mean A - B) when its comparison's test finds it at level alpha:
     * the Wilcoxon p below alpha (wilcoxon tests) or the t-interval on that side of zero (t_interval);
     * never for {@code none} or {@code bootstrap_descriptive}.
     */
    static boolean supports(SuiteReport.Comparison c, int sign, double alpha) {
        if (c.meanDifference() == null || Math.signum(c.meanDifference()) != sign) {
            return false;
        }
        return switch (c.test()) {
            case "wilcoxon_exact", "wilcoxon_normal_approximation" -> c.wilcoxon() != null
                    && c.wilcoxon().pValue() < alpha;
            case "t_interval" -> c.tInterval() != null && (sign < 0 ? c.tInterval().upper() < 0.0
                    : c.tInterval().lower() > 0.0);
            default -> false;
        };
    }

    private static int[][] singletons(List<String> ids, List<String> members) {
        return members.stream().map(id -> new int[] {ids.indexOf(id)}).toArray(int[][]::new);
    }

    /** Per sequence the mean over seeds, NaN where the method has no value. */
    static double[] sequenceMeans(List<RunEntry> runs, List<String> ids, String key) {
        double[] m = new double[ids.size()];
        for (int i = 0; i < ids.size(); i++) {
            double[] v = SuiteAnalysis.values(runs, ids.get(i), key);
            m[i] = v.length == 0 ? Double.NaN : SampleSummary.of(v).mean();
        }
        return m;
    }

    /** Mean of the finite values of the members, each weighted by its count (weight 1 when counts is null). */
    static double weightedMean(double[] values, boolean[] member, int[] counts) {
        double sum = 0.0;
        double w = 0.0;
        for (int i = 0; i < values.length; i++) {
            if (member[i] && Double.isFinite(values[i])) {
                int c = counts == null ? 1 : counts[i];
                sum += c * values[i];
                w += c;
            }
        }
        return w > 0.0 ? sum / w : Double.NaN;
    }

    private static int count(double[] values, boolean[] member) {
        int n = 0;
        for (int i = 0; i < values.length; i++) {
            if (member[i] && Double.isFinite(values[i])) {
                n++;
            }
        }
        return n;
    }

    /** Mid-ranks of the finite values (1 = best: smallest, or largest when {@code higher}); NaN stays NaN. */
    static double[] ranks(double[] v, boolean higher) {
        double[] r = new double[v.length];
        Arrays.fill(r, Double.NaN);
        for (int i = 0; i < v.length; i++) {
            if (!Double.isFinite(v[i])) {
                continue;
            }
            int better = 0;
            int ties = 0;
            for (int j = 0; j < v.length; j++) {
                if (j == i || !Double.isFinite(v[j])) {
                    continue;
                }
                if (v[j] == v[i]) {
                    ties++;
                } else if ((v[j] < v[i]) != higher) {
                    better++;
                }
            }
            r[i] = better + 1 + ties / 2.0;
        }
        return r;
    }
}
