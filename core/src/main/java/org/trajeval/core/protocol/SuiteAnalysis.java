package org.trajeval.core.protocol;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
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
import org.trajeval.core.stats.Interval;
import org.trajeval.core.stats.PairedTInterval;
import org.trajeval.core.stats.SampleSummary;
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
     */
    public record Settings(long seed, double level, int resamples) {
        /** @throws IllegalArgumentException on a level outside (0, 1) or fewer than 100 resamples */
        public Settings {
            if (!(level > 0.0 && level < 1.0)) {
                throw new IllegalArgumentException("confidence level must be in (0, 1), got " + level);
            }
            if (resamples < 100) {
                throw new IllegalArgumentException("bootstrap needs at least 100 resamples, got " + resamples);
            }
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
        SuiteReport.Proportion rate = null;
        if (!runs.isEmpty()) {
            Interval w = BinomialInterval.WILSON.of(failures, runs.size(), level);
            Interval cp = BinomialInterval.CLOPPER_PEARSON.of(failures, runs.size(), level);
            rate = new SuiteReport.Proportion(w.estimate(), level, new Bounds(w.lower(), w.upper()),
                    new Bounds(cp.lower(), cp.upper()));
        }
        List<SequenceSummary> scorePerSeq = new ArrayList<>();
        for (String s : sequences) {
            scorePerSeq.add(sequenceSummary(s, values(runs, s, SCORE)));
        }
        List<MetricSummary> metrics = new ArrayList<>();
        for (String key : metricKeys) {
            List<SequenceSummary> per = new ArrayList<>();
            List<Double> means = new ArrayList<>();
            for (String s : sequences) {
                SequenceSummary ss = sequenceSummary(s, values(runs, s, key));
                per.add(ss);
                if (ss.mean() != null) {
                    means.add(ss.mean());
                }
            }
            double[] m = means.stream().mapToDouble(Double::doubleValue).toArray();
            metrics.add(new MetricSummary(key, nullable(SampleSummary.of(m).mean()), per));
        }
        SampleSummary sc = SampleSummary.of(scores);
        return new MethodSummary(method, runs.size(), failures, rate,
                new SuiteReport.Summary(sc.n(), nullable(sc.mean()), nullable(sc.sd())), scorePerSeq, metrics);
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
        int n = pairs.size();
        double[] d = pairs.stream().mapToDouble(Paired::difference).toArray();
        Double mean = n == 0 ? null : SampleSummary.of(d).mean();
        Bounds t = null;
        Bounds boot = null;
        SuiteReport.Wilcoxon wil = null;
        if (n >= 2) {
            Interval ti = PairedTInterval.of(d, settings.level());
            t = new Bounds(ti.lower(), ti.upper());
            Interval bi = BootstrapInterval.ofMean(d, settings.level(), settings.resamples(),
                    settings.seed() * 1_000_003L + stream);
            boot = new Bounds(bi.lower(), bi.upper());
        }
        if (n >= 1) {
            WilcoxonSignedRank.Result w = WilcoxonSignedRank.test(d);
            wil = new SuiteReport.Wilcoxon(w.n(), w.zeros(), w.wPlus(), w.wMinus(), w.pValue(),
                    w.method().name().toLowerCase(Locale.ROOT));
        }
        return new Comparison(methodA, methodB, key, SCORE.equals(key) ? "higher" : "lower", n, mean, t, boot, wil,
                primary(n), pairs);
    }

    /** @return which test applies at n paired sequences, and why */
    public static String primary(int n) {
        if (n == 0) {
            return "none: no sequence where both methods have a value";
        }
        if (n == 1) {
            return "none: one paired sequence gives no interval and no test";
        }
        if (n < 6) {
            return String.format(Locale.ROOT, "bootstrap interval, descriptive only: with n = %d the smallest "
                    + "attainable Wilcoxon p is 2/2^%d = %.4f, so no difference can reach p < 0.05; the t-interval "
                    + "assumes normal differences", n, n, 2.0 / Math.pow(2, n));
        }
        if (n < 30) {
            return "Wilcoxon signed-rank (exact) with the bootstrap interval; the t-interval assumes normal "
                    + "differences, questionable at n = " + n;
        }
        return "t-interval (n = " + n + " >= 30: the mean difference is close to normal), cross-checked by "
                + "Wilcoxon (" + (n <= WilcoxonSignedRank.EXACT_MAX_N ? "exact" : "normal approximation") + ")";
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
