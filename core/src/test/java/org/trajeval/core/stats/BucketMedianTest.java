package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.trajeval.core.stats.MedianCases.assertBitsEqual;
import static org.trajeval.core.stats.MedianCases.shuffle;
import static org.trajeval.core.stats.MedianCases.sortedMiddle;
import static org.trajeval.core.stats.MedianCases.values;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The median of a few thousand values through {@link BucketMedian} (counts from
 * {@link BucketMedian#MIN_COUNT} up to below {@link RadixMedian#MIN_COUNT}) must be exactly the
 * middle of the values sorted by {@link Arrays#sort} (0.5 * (lower + upper) for even n, the
 * operation of {@link Selection#medianBySwapping}), whether the values come as one array or in
 * chunks.
 */
class BucketMedianTest {
    /** Sizes at both ends of the bucket path's range and the 10^4-pose runs; odd and even. */
    private static final int[] SIZES = {BucketMedian.MIN_COUNT, BucketMedian.MIN_COUNT + 1, 10_000, 10_001,
        RadixMedian.MIN_COUNT - 2, RadixMedian.MIN_COUNT - 1};

    @Test
    void halfNormalErrorsOfAnyScaleGiveTheSortedMiddle() {
        Random rnd = new Random(201);
        for (double scale : new double[] {1e-300, 1e-9, 0.05, 3.0, 1e300}) {
            for (int n : SIZES) {
                assertMedianIsSortedMiddle(values(n, i -> Math.abs(rnd.nextGaussian()) * scale),
                        "|N(0, " + scale + ")| n " + n);
            }
        }
    }

    @Test
    void moreThanHalfZerosGiveTheSortedMiddle() {
        Random rnd = new Random(202);
        for (int n : SIZES) {
            // zeros fall in the lowest bucket with every value 32 binades below the maximum
            assertMedianIsSortedMiddle(values(n, i -> rnd.nextInt(5) < 3 ? 0.0 : rnd.nextDouble()), "zeros n " + n);
            assertMedianIsSortedMiddle(values(n, i -> i == n / 2 ? 1.0 : 0.0), "all zero but one, n " + n);
        }
    }

    @Test
    void valuesSpreadOverMoreBinadesThanTheBucketsCoverGiveTheSortedMiddle() {
        Random rnd = new Random(203);
        for (int n : SIZES) {
            // 10^-60 .. 10^0: about 200 binades, the lower 170 share the lowest bucket
            assertMedianIsSortedMiddle(values(n, i -> Math.pow(10, -60 * rnd.nextDouble())), "log-uniform n " + n);
            assertMedianIsSortedMiddle(values(n, i -> i < n / 2 + 2 ? 1e-200 * (1 + rnd.nextDouble()) : 1.0),
                    "median far below the maximum, n " + n);
        }
    }

    @Test
    void lowerMiddleInAnotherBucketThanTheUpperGivesTheMeanOfTheTwo() {
        for (int n : new int[] {BucketMedian.MIN_COUNT, 10_000, RadixMedian.MIN_COUNT - 2}) {
            // ranks n/2 - 1 and n/2 are 1.0 and 3.0: buckets apart with empty buckets between; median 2.0 by hand
            double[] a = values(n, i -> i < n / 2 ? 1.0 - i * 1e-9 : 3.0 + (i - n / 2) * 1e-9);
            shuffle(a, new Random(n));
            assertMedianIsSortedMiddle(a, "two clusters, n " + n);
            assertBitsEqual(2.0, ErrorStatistics.ofInPlace(a.clone(), n).median(), "two clusters by hand, n " + n);
        }
    }

    @Test
    void equalValuesGiveThatValueAndHugeOnesTheirOverflowingMean() {
        for (int n : new int[] {BucketMedian.MIN_COUNT, 10_001, 10_000}) {
            assertMedianIsSortedMiddle(values(n, i -> 0.125), "all 0.125, n " + n);
            // 0.5 * (MAX + MAX) overflows to +infinity for even n, as the quickselect path computes it
            assertMedianIsSortedMiddle(values(n, i -> Double.MAX_VALUE), "all MAX_VALUE, n " + n);
            assertMedianIsSortedMiddle(values(n, i -> i % 3 == 0 ? Double.POSITIVE_INFINITY : 1.0), "with +inf, n " + n);
            assertMedianIsSortedMiddle(values(n, i -> Double.MIN_VALUE * (i % 7)), "subnormal, n " + n);
        }
    }

    @Test
    void theHistogramAloneGivesTheSortedMiddleAtBothEndsOfItsRange() {
        // BucketMedian itself, not through ErrorStatistics (whose quickselect fallback gives the same bits)
        Random rnd = new Random(206);
        for (int n : new int[] {BucketMedian.MIN_COUNT, BucketMedian.MIN_COUNT + 1, RadixMedian.MIN_COUNT - 1}) {
            double[] a = values(n, i -> Math.abs(rnd.nextGaussian()) * 0.05);
            BucketMedian histogram = BucketMedian.over(Arrays.stream(a).min().getAsDouble(),
                    Arrays.stream(a).max().getAsDouble());
            for (double v : a) {
                histogram.count(v);
            }
            assertBitsEqual(sortedMiddle(a), histogram.median(ValueChunks.of(a, n)), "histogram alone, n " + n);
        }
    }

    @Test
    void chunkedValuesGiveTheSameMedianAsOneArray() {
        Random rnd = new Random(204);
        double[] a = values(10_000, i -> Math.abs(rnd.nextGaussian()) * 0.1);
        ValueChunks chunks = ValueChunks.of(a.length, sink -> {
            for (int from = 0; from < a.length; from += 777) {
                int len = Math.min(777, a.length - from);
                sink.accept(Arrays.copyOfRange(a, from, from + len), len);
            }
        });
        assertBitsEqual(sortedMiddle(a), ErrorStatistics.of(chunks).median(), "777-value chunks");
    }

    @Test
    void negativeZeroNegativeOrNaNValuesAreLeftToQuickselect() {
        assertNull(BucketMedian.over(-0.0, 1.0));
        assertNull(BucketMedian.over(-1.0, 1.0));
        assertNull(BucketMedian.over(Double.NaN, 1.0));
        assertNull(BucketMedian.over(0.0, Double.NaN));
        assertNotNull(BucketMedian.over(0.0, Double.POSITIVE_INFINITY));
        Random rnd = new Random(205);
        double[] a = values(10_000, i -> i % 10 == 0 ? -0.0 : rnd.nextInt(3) == 0 ? 0.0 : rnd.nextDouble());
        // quickselect treats -0.0 and 0.0 as equal, so its bits (not the sort's) are the reference
        assertBitsEqual(Selection.medianBySwapping(a.clone(), a.length), ErrorStatistics.ofInPlace(a.clone(),
                a.length).median(), "-0.0 among zeros");
        a[17] = -2.5;
        assertBitsEqual(Selection.medianBySwapping(a.clone(), a.length), ErrorStatistics.ofInPlace(a.clone(),
                a.length).median(), "one negative value");
    }

    private static void assertMedianIsSortedMiddle(double[] a, String what) {
        assertBitsEqual(sortedMiddle(a), ErrorStatistics.ofInPlace(a.clone(), a.length).median(), what);
    }
}
