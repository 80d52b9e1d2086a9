package org.trajeval.core.stats;

import java.util.Arrays;
import java.util.SplittableRandom;

/**
 * Percentile bootstrap interval for the mean of per-sequence values d_1..d_n (e.g. paired
 * differences): draws B resamples of n whole sequences with replacement (never individual poses),
 * takes each resample's mean, and returns the alpha/2 and 1-alpha/2 empirical quantiles of those
 * means (type 7, linear interpolation). Seeded: the same values, level, B and seed give the same
 * interval on every machine.
 */
public final class BootstrapInterval {
    /** Default number of resamples. */
    public static final int DEFAULT_RESAMPLES = 4000;

    private BootstrapInterval() {
    }

    /**
     * @param values one value per sequence (at least 1)
     * @param level confidence level 1 - alpha
     * @param resamples number of resamples B (at least 100)
     * @param seed seed of the resampling
     * @throws IllegalArgumentException on no values or too few resamples
     */
    public static Interval ofMean(double[] values, double level, int resamples, long seed) {
        int n = values.length;
        if (n < 1) {
            throw new IllegalArgumentException("a bootstrap interval needs at least 1 value");
        }
        if (resamples < 100) {
            throw new IllegalArgumentException("bootstrap needs at least 100 resamples, got " + resamples);
        }
        SplittableRandom rng = new SplittableRandom(seed);
        double[] means = new double[resamples];
        for (int b = 0; b < resamples; b++) {
            double sum = 0.0;
            for (int i = 0; i < n; i++) {
                sum += values[rng.nextInt(n)];
            }
            means[b] = sum / n;
        }
        Arrays.sort(means);
        double alpha = 1.0 - level;
        double lo = quantile(means, alpha / 2.0);
        double hi = quantile(means, 1.0 - alpha / 2.0);
        return new Interval(SampleSummary.of(values).mean(), lo, hi, level);
    }

    /**
     * The percentile interval of bootstrap replicates: the alpha/2 and 1-alpha/2 type-7 quantiles
     * of the finite replicates (resamples whose statistic is undefined, NaN, are left out).
     *
     * @param estimate the statistic on the original sample
     * @param replicates the statistic on each resample
     * @param level confidence level 1 - alpha
     * @return the interval, or null when no replicate is finite
     */
    public static Interval percentile(double estimate, double[] replicates, double level) {
        double[] finite = Arrays.stream(replicates).filter(Double::isFinite).sorted().toArray();
        if (finite.length == 0) {
            return null;
        }
        double alpha = 1.0 - level;
        return new Interval(estimate, quantile(finite, alpha / 2.0), quantile(finite, 1.0 - alpha / 2.0), level);
    }

    /** Type-7 quantile (linear interpolation between order statistics) of sorted values. */
    static double quantile(double[] sorted, double p) {
        double h = (sorted.length - 1) * p;
        int lo = (int) Math.floor(h);
        int hi = Math.min(lo + 1, sorted.length - 1);
        return sorted[lo] + (h - lo) * (sorted[hi] - sorted[lo]);
    }
}
