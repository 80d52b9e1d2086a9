package org.trajeval.core.stats;

/**
 * Confidence interval for a failure rate when the runs come in clusters: the seeds of one
 * sequence share its difficulty, so they are not independent trials and the plain binomial
 * intervals are too narrow. Korn and Graubard's Clopper-Pearson interval with an effective
 * sample size (Korn and Graubard 1998, Survey Methodology 24:193-201; R survey's
 * {@code svyciprop(method = "beta")}):
 * <pre>
 *   p = F / N                                         F failures in N runs over g sequences
 *   v = g / (g - 1) * sum_s (f_s - p n_s)^2 / N^2      ratio-estimator variance, sequences resampled
 *   n* = min(N, p (1 - p) / v)                         (n* = N when v = 0, e.g. p = 0 or 1)
 *   n*_df = n* (t_{N-1, alpha/2} / t_{g-1, alpha/2})^2  degrees of freedom from g sequences, not N runs
 *   x* = p n*_df;  lower = Beta^-1(alpha/2; x*, n*_df - x* + 1) (0 when p = 0),
 *                  upper = Beta^-1(1 - alpha/2; x* + 1, n*_df - x*) (1 when p = 1)
 * </pre>
 * The design effect N / n* says how many runs count as one independent trial. With a single
 * sequence nothing is known about the clustering and the interval is [0, 1]. Worked example:
 * one failure on one of two sequences of 10 seeds each: p = 0.05, v = 2 (0.5^2 + 0.5^2)/400 =
 * 0.0025, n* = 0.0475/0.0025 = 19.
 */
public final class ClusteredProportion {
    /** Name of the method, as written in reports. */
    public static final String METHOD = "korn_graubard_sequence_clusters";

    private ClusteredProportion() {
    }

    /**
     * @param sequences g
     * @param designEffect N / n* (before the degrees-of-freedom correction), NaN with one sequence
     * @param effectiveTrials n*_df
     * @param interval interval around F / N
     */
    public record Result(int sequences, double designEffect, double effectiveTrials, Interval interval) {
    }

    /**
     * @param failures failures f_s per sequence
     * @param runs runs n_s per sequence (&gt;= f_s; sequences with no run are skipped)
     * @param level confidence level 1 - alpha
     * @throws IllegalArgumentException on counts out of range, ragged arrays or no run at all
     */
    public static Result of(int[] failures, int[] runs, double level) {
        if (failures.length != runs.length) {
            throw new IllegalArgumentException("one failure count per sequence needed: " + failures.length
                    + " counts for " + runs.length + " sequences");
        }
        int g = 0;
        long f = 0;
        long n = 0;
        for (int s = 0; s < runs.length; s++) {
            if (runs[s] < 0 || failures[s] < 0 || failures[s] > runs[s]) {
                throw new IllegalArgumentException("sequence " + s + ": need 0 <= failures <= runs, got "
                        + failures[s] + " of " + runs[s]);
            }
            if (runs[s] > 0) {
                g++;
                f += failures[s];
                n += runs[s];
            }
        }
        if (n == 0) {
            throw new IllegalArgumentException("a failure rate needs at least one run");
        }
        double p = (double) f / n;
        if (g < 2) {
            return new Result(g, Double.NaN, Double.NaN, new Interval(p, 0.0, 1.0, level));
        }
        double ss = 0.0;
        for (int s = 0; s < runs.length; s++) {
            if (runs[s] > 0) {
                double r = failures[s] - p * runs[s];
                ss += r * r;
            }
        }
        double v = g / (g - 1.0) * ss / ((double) n * n);
        double nStar = v > 0.0 ? Math.min(n, p * (1.0 - p) / v) : n;
        double q = (1.0 - level) / 2.0;
        double ratio = Quantiles.studentUpper(q, (int) Math.min(Integer.MAX_VALUE, n - 1))
                / Quantiles.studentUpper(q, g - 1);
        double nDf = nStar * ratio * ratio;
        double x = p * nDf;
        double lo = f == 0 ? 0.0 : Quantiles.beta(q, x, nDf - x + 1.0);
        double hi = f == n ? 1.0 : Quantiles.betaUpper(q, x + 1.0, nDf - x);
        return new Result(g, n / nStar, nDf, new Interval(p, lo, hi, level));
    }
}
