package org.trajeval.core.stats;

import java.util.Arrays;

/**
 * Summary of a set of non-negative error values e_1..e_n, in the unit of the errors (m or rad).
 * rmse = sqrt(sse / n); sse = sum e_i^2; std is the population standard deviation
 * sqrt(sum (e_i - mean)^2 / n), as evo reports it; median is the middle value, or the mean of
 * the two middle values when n is even.
 */
public record ErrorStatistics(double rmse, double mean, double median, double std, double min, double max,
        double sse, long n) {

    /** @throws IllegalArgumentException when n is negative */
    public ErrorStatistics {
        if (n < 0) {
            throw new IllegalArgumentException("n must be >= 0, got " + n);
        }
    }

    /**
     * Computes the statistics of {@code values[0..count)}; the array is not modified.
     * The empty set gives NaN for every statistic and n = 0.
     */
    public static ErrorStatistics of(double[] values, int count) {
        return ofInPlace(Arrays.copyOf(values, count), count);
    }

    /**
     * As {@link #of(double[], int)} but without a copy: {@code values[0..count)} may be reordered
     * (small or not non-negative input: the median is found by quickselect in place; large
     * non-negative input is only read). The sums are taken in index order before any reordering,
     * so the result equals {@link #of(double[], int)} bit for bit.
     *
     * <p>Large non-negative input (count &gt;= {@link RadixMedian#MIN_COUNT}, the usual errors)
     * is read twice: the first pass sums and histograms the values' top bits, the second sums the
     * squared deviations and copies the few values sharing the median's top bits, from which the
     * median is selected (see {@link RadixMedian} for the clustered cases needing more passes).
     */
    public static ErrorStatistics ofInPlace(double[] values, int count) {
        if (count == 0) {
            double nan = Double.NaN;
            return new ErrorStatistics(nan, nan, nan, nan, nan, nan, nan, 0);
        }
        if (count < RadixMedian.MIN_COUNT) {
            return ofSmall(values, count);
        }
        double sum = 0.0;
        double sse = 0.0;
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        int[] top = new int[RadixMedian.TOP_BUCKETS];
        for (int i = 0; i < count; i++) {
            double v = values[i];
            sum += v;
            sse += v * v;
            min = Math.min(min, v);
            max = Math.max(max, v);
            top[(int) (Double.doubleToRawLongBits(v) >>> RadixMedian.TOP_SHIFT)]++;
        }
        double mean = sum / count;
        RadixMedian radix = RadixMedian.start(top, values, count, min, max);
        double sq;
        double median;
        if (radix == null) {
            sq = squaredDeviations(values, count, mean);
            median = Selection.medianBySwapping(values, count);
        } else {
            sq = radix.done() ? squaredDeviations(values, count, mean) : radix.nextPass(values, mean);
            while (!radix.done()) {
                radix.nextPass(values, mean);
            }
            median = radix.median();
        }
        return new ErrorStatistics(Math.sqrt(sse / count), mean, median, Math.sqrt(sq / count), min, max, sse, count);
    }

    /** Two passes in index order for the sums, then the median by quickselect (reorders). */
    private static ErrorStatistics ofSmall(double[] values, int count) {
        double sum = 0.0;
        double sse = 0.0;
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < count; i++) {
            double v = values[i];
            sum += v;
            sse += v * v;
            min = Math.min(min, v);
            max = Math.max(max, v);
        }
        double mean = sum / count;
        double sq = squaredDeviations(values, count, mean);
        double median = Selection.medianBySwapping(values, count);
        return new ErrorStatistics(Math.sqrt(sse / count), mean, median, Math.sqrt(sq / count), min, max, sse, count);
    }

    /** @return sum over i in index order of (values_i - mean)^2 */
    private static double squaredDeviations(double[] values, int count, double mean) {
        double sq = 0.0;
        for (int i = 0; i < count; i++) {
            double d = values[i] - mean;
            sq += d * d;
        }
        return sq;
    }

    /** Computes the statistics of all of {@code values}. */
    public static ErrorStatistics of(double[] values) {
        return of(values, values.length);
    }
}
