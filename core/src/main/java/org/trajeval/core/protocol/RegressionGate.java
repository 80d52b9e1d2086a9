package org.trajeval.core.protocol;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.BiFunction;
import org.trajeval.core.report.SuiteReport.Bounds;
import org.trajeval.core.report.SuiteReport.Comparison;
import org.trajeval.core.report.SuiteReport.Paired;
import org.trajeval.core.report.SuiteReport.RunEntry;

/**
 * The regression gate: is a candidate worse than its baseline, beyond a tolerance, with a given
 * confidence? It applies the suite's paired statistics ({@link SuiteAnalysis#compare}) to the runs
 * both sides have for the same (sequence, seed).
 *
 * <p>Rule, per method and metric: d_s = c_s - b_s per sequence (means over the common seeds);
 * margin = tolerance x |mean over sequences of b_s| (in the metric's unit). The gate takes the
 * two-sided intervals at level 2C' - 1 of the mean difference, whose lower bounds are one-sided C'
 * lower bounds: the t-interval and the bootstrap over sequences, and of the two the bound less
 * favourable to a regression (a gate should fail only when both agree: at n = 8 the percentile
 * bootstrap alone is about as narrow as a z-interval and flagged 8 % of equal-quality pairs at
 * nominal 5 %). A lower-is-better metric regresses when that lower bound exceeds +margin (the
 * candidate is worse by more than the tolerance); the score (higher is better) when the upper
 * bound is below -margin. {@link #gateAll} gates k (method, metric) pairs at once with
 * C' = 1 - (1 - C) / k (Bonferroni), so a gate of equal-quality runs fails with probability at most
 * about 1 - C whatever k. Fewer than 2 paired sequences give no interval: inconclusive, which does
 * not fail the gate but is reported.
 *
 * <p>Example: tolerance 5 %, baseline ATE 0.100 m, so margin 0.005 m; the candidate's one-sided
 * 95 % lower bound of the mean difference is 0.021 m &gt; 0.005 m: regression.
 */
public final class RegressionGate {
    private RegressionGate() {
    }

    /** The gate's finding for one method and metric. */
    public enum Verdict {
        /** No regression beyond the tolerance at the chosen confidence. */
        PASS,
        /** Worse beyond the tolerance at the chosen confidence. */
        REGRESSION,
        /** Fewer than 2 paired sequences: no interval, no decision. */
        INCONCLUSIVE
    }

    /**
     * @param confidence one-sided confidence C in (0.5, 1)
     * @param seed bootstrap seed
     * @param resamples bootstrap resamples
     */
    public record Settings(double confidence, long seed, int resamples) {
        /** @throws IllegalArgumentException on C outside (0.5, 1) or fewer than 100 resamples */
        public Settings {
            if (!(confidence > 0.5 && confidence < 1.0)) {
                throw new IllegalArgumentException("--confidence must be in (0.5, 1), found " + confidence);
            }
            if (resamples < 100) {
                throw new IllegalArgumentException("--resamples must be at least 100, found " + resamples);
            }
        }
    }

    /**
     * One gated (method, metric).
     *
     * @param method method name
     * @param metric metric key (with unit), or "score"
     * @param tolerance allowed relative worsening (0.05 = 5 %)
     * @param higherIsBetter true for the score
     * @param n paired sequences
     * @param baselineMean mean over sequences of the baseline's per-sequence means (metric unit), NaN when n = 0
     * @param candidateMean same for the candidate
     * @param margin tolerance x |baselineMean| (metric unit)
     * @param bound the one-sided bound compared with the margin (lower bound, or upper for the
     *     score), NaN when inconclusive
     * @param interval which interval gave the bound (the less favourable to a regression): "t" or
     *     "bootstrap", or "none"
     * @param verdict the finding
     * @param perSequence paired values: a = candidate, b = baseline
     */
    public record Finding(String method, String metric, double tolerance, boolean higherIsBetter, int n,
            double baselineMean, double candidateMean, double margin, double bound, String interval, Verdict verdict,
            List<Paired> perSequence) {
        /** @return (candidate - baseline) / |baseline|, NaN when undefined */
        public double relativeChange() {
            return (candidateMean - baselineMean) / Math.abs(baselineMean);
        }

        /** @return whether this sequence alone is worse than the tolerance allows */
        public boolean sequenceWorse(Paired p) {
            double allowed = tolerance * Math.abs(p.b());
            return higherIsBetter ? p.difference() < -allowed : p.difference() > allowed;
        }
    }

    /**
     * Gates one method on one metric.
     *
     * @param method method name (the same on both sides)
     * @param baseline the baseline's runs of the method
     * @param candidate the candidate's runs of the method
     * @param sequences sequences to pair over, in report order
     * @param metric metric key, or {@link SuiteAnalysis#SCORE}
     * @param tolerance allowed relative worsening, &ge; 0
     * @param settings confidence and bootstrap
     * @param stream index mixed into the bootstrap seed
     */
    public static Finding gate(String method, List<RunEntry> baseline, List<RunEntry> candidate,
            List<String> sequences, String metric, double tolerance, Settings settings, int stream) {
        requireTolerance(tolerance);
        Set<String> inBase = new HashSet<>();
        baseline.forEach(r -> inBase.add(r.sequence() + "\u0000" + r.seed()));
        Set<String> inCand = new HashSet<>();
        candidate.forEach(r -> inCand.add(r.sequence() + "\u0000" + r.seed()));
        List<RunEntry> b = baseline.stream().filter(r -> inCand.contains(r.sequence() + "\u0000" + r.seed())).toList();
        List<RunEntry> c = candidate.stream().filter(r -> inBase.contains(r.sequence() + "\u0000" + r.seed())).toList();
        SuiteAnalysis.Settings two = twoSided(settings);
        return decide(method, metric, tolerance, SuiteAnalysis.compare("candidate", c, "baseline", b, sequences, metric,
                two, stream));
    }

    /**
     * Gates one method on one metric from per-sequence means formed elsewhere (the store pairs and
     * averages in SQL): the same rule as {@link #gate}, given what it would have paired.
     *
     * @param perSequence per paired sequence: a = the candidate's mean over the common seeds, b = the
     *     baseline's, difference = a - b (metric unit); in a fixed order (the bootstrap resamples by index)
     */
    public static Finding gatePaired(String method, String metric, double tolerance, List<Paired> perSequence,
            Settings settings, int stream) {
        requireTolerance(tolerance);
        return decide(method, metric, tolerance, SuiteAnalysis.compare("candidate", "baseline", metric, perSequence,
                twoSided(settings), stream));
    }

    private static SuiteAnalysis.Settings twoSided(Settings settings) {
        return new SuiteAnalysis.Settings(settings.seed(), 2 * settings.confidence() - 1, settings.resamples());
    }

    private static void requireTolerance(double tolerance) {
        if (!(tolerance >= 0 && Double.isFinite(tolerance))) {
            throw new IllegalArgumentException("tolerance must be a finite fraction >= 0, found " + tolerance);
        }
    }

    private static Finding decide(String method, String metric, double tolerance, Comparison cmp) {
        boolean higher = SuiteAnalysis.SCORE.equals(metric);
        int n = cmp.n();
        double baseMean = mean(cmp.perSequence(), false);
        double candMean = mean(cmp.perSequence(), true);
        double margin = tolerance * Math.abs(baseMean);
        Bounds t = cmp.tInterval();
        Bounds boot = cmp.bootstrap();
        if (t == null || boot == null) {
            return new Finding(method, metric, tolerance, higher, n, baseMean, candMean, margin, Double.NaN, "none",
                    Verdict.INCONCLUSIVE, cmp.perSequence());
        }
        // the bound less favourable to a regression: the lower of the upper bounds' complements
        double tBound = higher ? t.upper() : t.lower();
        double bBound = higher ? boot.upper() : boot.lower();
        boolean tWins = higher ? tBound >= bBound : tBound <= bBound;
        double bound = tWins ? tBound : bBound;
        boolean worse = higher ? bound < -margin : bound > margin;
        return new Finding(method, metric, tolerance, higher, n, baseMean, candMean, margin, bound,
                tWins ? "t" : "bootstrap", worse ? Verdict.REGRESSION : Verdict.PASS, cmp.perSequence());
    }

    /**
     * Gates every method of the candidate that the baseline has, on every metric of {@code tolerances},
     * each at C' = 1 - (1 - C) / k for k (method, metric) pairs.
     *
     * @param baseline baseline runs (any methods)
     * @param candidate candidate runs
     * @param methods methods to gate, in output order
     * @param sequences sequences to pair over
     * @param tolerances metric key to allowed relative worsening, in output order
     */
    public static List<Finding> gateAll(List<RunEntry> baseline, List<RunEntry> candidate, List<String> methods,
            List<String> sequences, Map<String, Double> tolerances, Settings settings) {
        List<Finding> out = new ArrayList<>();
        Settings each = eachOf(settings, methods.size() * tolerances.size());
        int stream = 0;
        for (String m : methods) {
            List<RunEntry> b = baseline.stream().filter(r -> r.method().equals(m)).toList();
            List<RunEntry> c = candidate.stream().filter(r -> r.method().equals(m)).toList();
            for (Map.Entry<String, Double> t : tolerances.entrySet()) {
                out.add(gate(m, b, c, sequences, t.getKey(), t.getValue(), each, stream++));
            }
        }
        return out;
    }

    /**
     * {@link #gateAll} on per-sequence means formed elsewhere: the same Bonferroni share and bootstrap
     * streams, so the same pairs give the same findings.
     *
     * @param methods methods to gate, in output order
     * @param tolerances metric key to allowed relative worsening, in output order
     * @param perSequence (method, metric) to its paired per-sequence means (see {@link #gatePaired})
     */
    public static List<Finding> gateAllPaired(List<String> methods, Map<String, Double> tolerances,
            BiFunction<String, String, List<Paired>> perSequence, Settings settings) {
        List<Finding> out = new ArrayList<>();
        Settings each = eachOf(settings, methods.size() * tolerances.size());
        int stream = 0;
        for (String m : methods) {
            for (Map.Entry<String, Double> t : tolerances.entrySet()) {
                out.add(gatePaired(m, t.getKey(), t.getValue(), perSequence.apply(m, t.getKey()), each, stream++));
            }
        }
        return out;
    }

    /** @return the settings of one of k gated pairs: C' = 1 - (1 - C) / k (Bonferroni) */
    private static Settings eachOf(Settings settings, int k) {
        return new Settings(1 - (1 - settings.confidence()) / Math.max(1, k), settings.seed(), settings.resamples());
    }

    private static double mean(List<Paired> ps, boolean candidate) {
        if (ps.isEmpty()) {
            return Double.NaN;
        }
        double s = 0;
        for (Paired p : ps) {
            s += candidate ? p.a() : p.b();
        }
        return s / ps.size();
    }
}
