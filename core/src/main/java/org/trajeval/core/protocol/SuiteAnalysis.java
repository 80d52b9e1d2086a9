package org.trajeval.core.protocol;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.Bounds;
import org.trajeval.core.report.SuiteReport.Comparison;
import org.trajeval.core.report.SuiteReport.MethodSummary;
import org.trajeval.core.report.SuiteReport.MetricSummary;
import org.trajeval.core.report.SuiteReport.Paired;
import org.trajeval.core.report.SuiteReport.RunEntry;
import org.trajeval.core.report.SuiteReport.SequenceSummary;
import org.trajeval.core.stats.BinomialInterval;
import org.trajeval.core.stats.BootstrapInterval;
import org.trajeval.core.stats.ClusteredProportion;
import org.trajeval.core.stats.HodgesLehmann;
import org.trajeval.core.stats.Interval;
import org.trajeval.core.stats.PairedTInterval;
import org.trajeval.core.stats.PowerPlanning;
import org.trajeval.core.stats.SampleSummary;
import org.trajeval.core.stats.VarianceComponents;
import org.trajeval.core.stats.WilcoxonSignedRank;

/**
 * The statistics of a suite (lesson sections 4 and 7), computed from its runs.
 *
 * <p>Per method and sequence, a metric is summarised over the successful seeds by the mean and the
 * sample standard deviation (K-1); the score S over all seeds, a failed run scoring 0. The failure
 * rate f/n comes with Wilson and Clopper-Pearson intervals. Two methods are compared on the
 * sequences where both have a value: d_s = a_s - b_s (a_s the mean over seeds), with the t-interval
 * d_bar +- t_{n-1,1-alpha/2} s_d / sqrt(n), a seeded bootstrap resampling whole sequences, and the
 * Wilcoxon signed-rank test.
 */
public final class SuiteAnalysis {
    /** Key of the normalised score in comparisons. */
    public static final String SCORE = "score";

    /**
     * @param seed seed of the bootstrap resampling
     * @param level confidence level of every interval
     * @param resamples bootstrap resamples B
     * @param power power 1 - beta of the planning figures, in (0.5, 1)
     * @param targets per metric key, a mean difference whose needed number of sequences is reported
     */
    public record Settings(long seed, double level, int resamples, double power, Map<String, Double> targets) {
        /** @throws IllegalArgumentException on a level outside (0, 1), fewer than 100 resamples, a bad power or target */
        public Settings {
            if (!(level > 0.0 && level < 1.0)) {
                throw new IllegalArgumentException("confidence level must be in (0, 1), got " + level);
            }
            if (resamples < 100) {
                throw new IllegalArgumentException("bootstrap needs at least 100 resamples, got " + resamples);
            }
            if (!(power > 0.5 && power < 1.0)) {
                throw new IllegalArgumentException("power must be in (0.5, 1), got " + power);
            }
            targets = Map.copyOf(targets);
            targets.forEach((k, v) -> {
                if (!(Double.isFinite(v) && v != 0.0)) {
                    throw new IllegalArgumentException("difference to detect for '" + k
                            + "' must be a finite non-zero number, got " + v);
                }
            });
        }

        /** Power {@link PowerPlanning#DEFAULT_POWER}, no target difference. */
        public Settings(long seed, double level, int resamples) {
            this(seed, level, resamples, PowerPlanning.DEFAULT_POWER, Map.of());
        }

        /** 95 %, 4000 resamples. */
        public static Settings defaults(long seed) {
            return new Settings(seed, 0.95, BootstrapInterval.DEFAULT_RESAMPLES);
        }
    }

    private SuiteAnalysis() {
    }

    /**
     * Summarises one method.
     *
     * @param method the method's name
     * @param sequences the evaluated sequences, in report order
     * @param runs the method's runs (evaluated sequences, common seeds only)
     * @param metricKeys the score metrics' keys
     * @param level confidence level of the failure-rate intervals
     */
    public static MethodSummary summarise(String method, List<String> sequences, List<RunEntry> runs,
            List<String> metricKeys, double level) {
        int failures = 0;
        double[] scores = new double[runs.size()];
        for (int i = 0; i < runs.size(); i++) {
            if (!runs.get(i).ok()) {
                failures++;
            }
            scores[i] = runs.get(i).score();
        }
        SuiteReport.Proportion rate = failureRate(sequences, runs, level);
        List<SequenceSummary> scorePerSeq = new ArrayList<>();
        double[][] scoreGroups = new double[sequences.size()][];
        for (int i = 0; i < sequences.size(); i++) {
            scoreGroups[i] = values(runs, sequences.get(i), SCORE);
            scorePerSeq.add(sequenceSummary(sequences.get(i), scoreGroups[i]));
        }
        List<MetricSummary> metrics = new ArrayList<>();
        for (String key : metricKeys) {
            List<SequenceSummary> per = new ArrayList<>();
            List<Double> means = new ArrayList<>();
            double[][] groups = new double[sequences.size()][];
            for (int i = 0; i < sequences.size(); i++) {
                groups[i] = values(runs, sequences.get(i), key);
                SequenceSummary ss = sequenceSummary(sequences.get(i), groups[i]);
                per.add(ss);
                if (ss.mean() != null) {
                    means.add(ss.mean());
                }
            }
            double[] m = means.stream().mapToDouble(Double::doubleValue).toArray();
            metrics.add(new MetricSummary(key, nullable(SampleSummary.of(m).mean()), per, variance(groups)));
        }
        SampleSummary sc = SampleSummary.of(scores);
        return new MethodSummary(method, runs.size(), failures, rate,
                new SuiteReport.Summary(sc.n(), nullable(sc.mean()), nullable(sc.sd())), scorePerSeq, metrics,
                variance(scoreGroups));
    }

    /**
     * The failure rate f/n of some runs with its Wilson, Clopper-Pearson and clustered (Korn-Graubard,
     * seeds of one sequence as a cluster) intervals; null without runs.
     */
    static SuiteReport.Proportion failureRate(List<String> sequences, List<RunEntry> runs, double level) {
        if (runs.isEmpty()) {
            return null;
        }
        int failures = (int) runs.stream().filter(r -> !r.ok()).count();
        Interval w = BinomialInterval.WILSON.of(failures, runs.size(), level);
        Interval cp = BinomialInterval.CLOPPER_PEARSON.of(failures, runs.size(), level);
        return new SuiteReport.Proportion(w.estimate(), level, new Bounds(w.lower(), w.upper()),
                new Bounds(cp.lower(), cp.upper()), clustered(sequences, runs, level));
    }

    /** Korn-Graubard interval of the failure rate with the runs clustered by sequence. */
    private static SuiteReport.ClusteredBounds clustered(List<String> sequences, List<RunEntry> runs, double level) {
        int[] f = new int[sequences.size()];
        int[] n = new int[sequences.size()];
        for (RunEntry r : runs) {
            int i = sequences.indexOf(r.sequence());
            if (i >= 0) {
                n[i]++;
                if (!r.ok()) {
                    f[i]++;
                }
            }
        }
        if (Arrays.stream(n).sum() == 0) {
            return null;
        }
        ClusteredProportion.Result c = ClusteredProportion.of(f, n, level);
        return new SuiteReport.ClusteredBounds(ClusteredProportion.METHOD, c.sequences(),
                nullable(c.designEffect()), nullable(c.effectiveTrials()), c.interval().lower(),
                c.interval().upper());
    }

    /** @return the variance split of per-sequence groups of values, null when not estimable */
    static SuiteReport.VarianceSplit variance(double[][] groups) {
        VarianceComponents.Result v = VarianceComponents.of(groups);
        if (v == null) {
            return null;
        }
        return new SuiteReport.VarianceSplit(v.sequences(), v.values(), v.seedsPerSequence(),
                Math.sqrt(v.sequenceVariance()), Math.sqrt(v.seedVariance()), nullable(v.sequenceShare()),
                v.advice().name().toLowerCase(Locale.ROOT));
    }

    /**
     * Paired comparison of two methods on one metric.
     *
     * @param methodA label of method A
     * @param runsA its runs
     * @param methodB label of method B
     * @param runsB its runs
     * @param sequences the sequences to pair over, in report order
     * @param key metric key, or {@link #SCORE}
     * @param settings statistics settings
     * @param stream index of this comparison, mixed into the bootstrap seed
     */
    public static Comparison compare(String methodA, List<RunEntry> runsA, String methodB, List<RunEntry> runsB,
            List<String> sequences, String key, Settings settings, int stream) {
        List<Paired> pairs = new ArrayList<>();
        for (String s : sequences) {
            double[] a = values(runsA, s, key);
            double[] b = values(runsB, s, key);
            if (a.length > 0 && b.length > 0) {
                double ma = SampleSummary.of(a).mean();
                double mb = SampleSummary.of(b).mean();
                pairs.add(new Paired(s, ma, mb, ma - mb));
            }
        }
        return compare(methodA, methodB, key, pairs, settings, stream);
    }

    /**
     * Paired comparison from per-sequence means already formed (e.g. aggregated in a database):
     * the same statistics as {@link #compare(String, List, String, List, List, String, Settings, int)}
     * over d_s = a_s - b_s, in the order given (the bootstrap resamples by index).
     *
     * @param methodA label of method A
     * @param methodB label of method B
     * @param key metric key, or {@link #SCORE}
     * @param pairs per sequence: a = A's mean, b = B's mean, difference = a - b
     * @param settings statistics settings
     * @param stream index of this comparison, mixed into the bootstrap seed
     */
    public static Comparison compare(String methodA, String methodB, String key, List<Paired> pairs,
            Settings settings, int stream) {
        int n = pairs.size();
        double[] d = pairs.stream().mapToDouble(Paired::difference).toArray();
        Double mean = n == 0 ? null : SampleSummary.of(d).mean();
        boolean higher = SCORE.equals(key);
        Bounds t = null;
        Bounds boot = null;
        SuiteReport.Wilcoxon wil = null;
        SuiteReport.HodgesLehmannEntry hl = null;
        SuiteReport.Wins wins = null;
        SuiteReport.Planning planning = null;
        WilcoxonSignedRank.Result w = null;
        if (n >= 2) {
            Interval ti = PairedTInterval.of(d, settings.level());
            t = new Bounds(ti.lower(), ti.upper());
            Interval bi = BootstrapInterval.ofMean(d, settings.level(), settings.resamples(),
                    settings.seed() * 1_000_003L + stream);
            boot = new Bounds(bi.lower(), bi.upper());
            double sd = SampleSummary.of(d).sd();
            Double target = settings.targets().get(key);
            Integer needed = null;
            if (target != null) {
                int k = PowerPlanning.sequencesNeeded(sd, target, settings.level(), settings.power());
                needed = k < 0 ? null : k;
            }
            planning = new SuiteReport.Planning(sd, settings.power(),
                    PowerPlanning.minimumDetectableDifference(sd, n, settings.level(), settings.power()), target,
                    needed);
        }
        if (n >= 1) {
            w = WilcoxonSignedRank.test(d);
            wil = new SuiteReport.Wilcoxon(w.n(), w.zeros(), w.wPlus(), w.wMinus(), w.pValue(),
                    w.method().name().toLowerCase(Locale.ROOT));
            HodgesLehmann.Result h = HodgesLehmann.of(d, settings.level());
            hl = new SuiteReport.HodgesLehmannEntry(h.estimate(), h.interval().lower(), h.interval().upper(),
                    settings.level(), h.achievedLevel(), h.method().name().toLowerCase(Locale.ROOT));
            int aBetter = 0;
            int ties = 0;
            for (double v : d) {
                if (v == 0.0) {
                    ties++;
                } else if ((v < 0.0) != higher) {
                    aBetter++;
                }
            }
            wins = new SuiteReport.Wins(aBetter, ties, n - aBetter - ties, aBetter / (double) n);
        }
        int nonzero = w == null ? 0 : w.n();
        Choice choice = choose(n, w);
        return new Comparison(methodA, methodB, key, higher ? "higher" : "lower", n, nonzero, mean, t, boot, wil,
                null, hl, wins, planning, choice.test(), choice.why(), pairs);
    }

    /**
     * Which test the conclusion rests on, and why.
     *
     * @param test machine-readable name
     * @param why one sentence for a person
     */
    public record Choice(String test, String why) {
    }

    /**
     * The test that applies at n paired sequences with the Wilcoxon result {@code w} (its n counts the
     * non-zero differences, its method says exact or normal approximation).
     *
     * @param n paired sequences
     * @param w Wilcoxon result, null when n = 0
     */
    public static Choice choose(int n, WilcoxonSignedRank.Result w) {
        if (n == 0) {
            return new Choice("none", "none: no sequence where both methods have a value");
        }
        if (n == 1) {
            return new Choice("none", "none: one paired sequence gives no interval and no test");
        }
        int m = w.n();
        String variant = w.method() == WilcoxonSignedRank.Method.NORMAL_APPROXIMATION
                ? "normal approximation" : "exact";
        String wilcoxon = "Wilcoxon signed-rank (" + variant + ", on " + m + " non-zero of " + n + " differences)";
        if (n >= 30) {
            return new Choice("t_interval", "t-interval (n = " + n + " >= 30: the mean difference is close to "
                    + "normal), cross-checked by " + (m == 0 ? "nothing: every difference is zero" : wilcoxon));
        }
        if (m < 6) {
            return new Choice("bootstrap_descriptive", String.format(Locale.ROOT, "bootstrap interval, descriptive "
                    + "only: with %d non-zero of %d differences the smallest attainable Wilcoxon p is %s, so no "
                    + "difference can reach p < 0.05; the t-interval assumes normal differences", m, n,
                    m == 0 ? "1" : String.format(Locale.ROOT, "2/2^%d = %.4f", m, 2.0 / Math.pow(2, m))));
        }
        return new Choice(w.method() == WilcoxonSignedRank.Method.NORMAL_APPROXIMATION
                ? "wilcoxon_normal_approximation" : "wilcoxon_exact", wilcoxon + " with the bootstrap interval; "
                + "the t-interval assumes normal differences, questionable at n = " + n);
    }

    /** @return the values of one metric of the runs on one sequence: ok runs only, or every run for the score */
    static double[] values(List<RunEntry> runs, String sequence, String key) {
        List<Double> out = new ArrayList<>();
        for (RunEntry r : runs) {
            if (!r.sequence().equals(sequence)) {
                continue;
            }
            if (SCORE.equals(key)) {
                out.add(r.score());
            } else if (r.ok() && r.metrics() != null && r.metrics().get(key) != null) {
                out.add(r.metrics().get(key));
            }
        }
        return out.stream().mapToDouble(Double::doubleValue).toArray();
    }

    private static SequenceSummary sequenceSummary(String s, double[] v) {
        SampleSummary ss = SampleSummary.of(v);
        return new SequenceSummary(s, ss.n(), nullable(ss.mean()), nullable(ss.sd()));
    }

    /** @return null for NaN, so JSON never holds NaN */
    static Double nullable(double v) {
        return Double.isFinite(v) ? v : null;
    }
}
