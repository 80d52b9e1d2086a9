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
     * (fewer than {@link BucketMedian#MIN_COUNT} values, or not non-negative input: the median is
     * found by quickselect in place; more non-negative values are only read). The sums are taken
     * in index order before any reordering, so the result equals {@link #of(double[], int)} bit
     * for bit.
     *
     * <p>Large non-negative input (count &gt;= {@link RadixMedian#MIN_COUNT}, the usual errors)
     * is read twice: the first pass sums and histograms the values' top bits, the second sums the
     * squared deviations and copies the few values sharing the median's top bits, from which the
     * median is selected (see {@link RadixMedian} for the clustered cases needing more passes).
     */
    public static ErrorStatistics ofInPlace(double[] values, int count) {
        return compute(ValueChunks.of(values, count), values);
    }

    /**
     * The statistics of values read chunk by chunk, e.g. errors computed afresh at each reading
     * instead of stored: the same numbers, bit for bit, as {@link #of(double[], int)} on the
     * values in index order. Large non-negative input (at least {@link RadixMedian#MIN_COUNT}
     * values) is read twice (rarely more, see {@link RadixMedian}); from {@link BucketMedian#MIN_COUNT}
     * values up it is read three times (sums, squared deviations with the bucket counts, and a copy
     * of the median's buckets only); anything else is copied into an array once, for its median.
     */
    public static ErrorStatistics of(ValueChunks values) {
        return compute(values, null);
    }

    /**
     * Sums in index order (sum, sse, min, max, then the squared deviations), and the median: by
     * radix selection on the values' bits for large non-negative input (the first histogram taken
     * in the sums' pass), by one bucket histogram ({@link BucketMedian}, taken in the squared
     * deviations' pass) for a few thousand non-negative values, else by quickselect on
     * {@code array} (reordered) or on a copy when null.
     */
    private static ErrorStatistics compute(ValueChunks values, double[] array) {
        int count = values.size();
        if (count == 0) {
            double nan = Double.NaN;
            return new ErrorStatistics(nan, nan, nan, nan, nan, nan, nan, 0);
        }
        int[] top = count < RadixMedian.MIN_COUNT ? null : new int[RadixMedian.TOP_BUCKETS];
        double[] sums = sums(values, top);
        double sse = sums[1];
        double min = sums[2];
        double max = sums[3];
        double mean = sums[0] / count;
        RadixMedian radix = top == null ? null : RadixMedian.start(top, values, count, min, max);
        double sq;
        double median;
        if (radix != null) {
            sq = radix.done() ? squaredDeviations(values, mean, null) : radix.nextPass(values, mean);
            while (!radix.done()) {
                radix.nextPass(values, mean);
            }
            median = radix.median();
        } else {
            BucketMedian buckets = count >= BucketMedian.MIN_COUNT ? BucketMedian.over(min, max) : null;
            sq = squaredDeviations(values, mean, buckets);
            median = buckets != null ? buckets.median(values)
                    : Selection.medianBySwapping(array != null ? array : copy(values), count);
        }
        return new ErrorStatistics(Math.sqrt(sse / count), mean, median, Math.sqrt(sq / count), min, max, sse, count);
    }

    /**
     * @param top when not null, counts each value's top {@link RadixMedian#TOP_BITS} bits
     * @return {sum, sse, min, max} of the values, summed in index order
     */
    private static double[] sums(ValueChunks values, int[] top) {
        double[] sums = {0.0, 0.0, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};
        values.forEach((a, len) -> {
            double sum = sums[0];
            double sse = sums[1];
            double min = sums[2];
            double max = sums[3];
            for (int i = 0; i < len; i++) {
                double v = a[i];
                sum += v;
                sse += v * v;
                min = Math.min(min, v);
                max = Math.max(max, v);
                if (top != null) {
                    top[(int) (Double.doubleToRawLongBits(v) >>> RadixMedian.TOP_SHIFT)]++;
                }
            }
            sums[0] = sum;
            sums[1] = sse;
            sums[2] = min;
            sums[3] = max;
        });
        return sums;
    }

    /**
     * @param buckets when not null, counts each value for its median
     * @return sum over i in index order of (values_i - mean)^2
     */
    private static double squaredDeviations(ValueChunks values, double mean, BucketMedian buckets) {
        double[] sq = {0.0};
        values.forEach((a, len) -> {
            double s = sq[0];
            for (int i = 0; i < len; i++) {
                double v = a[i];
                double d = v - mean;
                s += d * d;
                if (buckets != null) {
                    buckets.count(v);
                }
            }
            sq[0] = s;
        });
        return sq[0];
    }

    /** @return the values in one new array */
    private static double[] copy(ValueChunks values) {
        double[] copy = new double[values.size()];
        int[] filled = {0};
        values.forEach((a, len) -> {
            System.arraycopy(a, 0, copy, filled[0], len);
            filled[0] += len;
        });
        return copy;
    }

    /** Computes the statistics of all of {@code values}. */
    public static ErrorStatistics of(double[] values) {
        return of(values, values.length);
    }
}
