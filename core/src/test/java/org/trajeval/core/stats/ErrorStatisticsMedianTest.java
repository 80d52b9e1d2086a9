package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.trajeval.core.stats.MedianCases.assertBitsEqual;
import static org.trajeval.core.stats.MedianCases.shuffle;
import static org.trajeval.core.stats.MedianCases.sortedMiddle;
import static org.trajeval.core.stats.MedianCases.values;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The median of {@link ErrorStatistics#ofInPlace} (radix narrowing for large non-negative input,
 * quickselect otherwise) must be exactly the middle of the sorted values (mean of the two middle
 * values for even n); the reference here sorts a copy with {@link Arrays#sort}. The other
 * statistics must be the sums taken in index order, recomputed here by their definitions.
 */
class ErrorStatisticsMedianTest {
    /** Sizes around the radix threshold, one between, two large ones; odd and even. */
    private static final int[] SIZES = {RadixMedian.MIN_COUNT - 1, RadixMedian.MIN_COUNT,
        RadixMedian.MIN_COUNT + 1, 131_072, 200_001, 1_000_000};

    @Test
    void medianOfUniformValuesIsTheSortedMiddle() {
        Random rnd = new Random(101);
        for (int n : SIZES) {
            assertMedianIsSortedMiddle(values(n, i -> rnd.nextDouble()), "uniform n " + n);
        }
    }

    @Test
    void medianOfHalfNormalErrorsOfAnyScaleIsTheSortedMiddle() {
        Random rnd = new Random(102);
        for (double scale : new double[] {1e-9, 0.01, 0.05, 3.0, 1e6}) {
            for (int n : new int[] {200_001, 200_000}) {
                assertMedianIsSortedMiddle(values(n, i -> Math.abs(rnd.nextGaussian()) * scale),
                        "|N(0, " + scale + ")| n " + n);
            }
        }
    }

    @Test
    void medianOfValuesClusteredInOneTopBucketIsTheSortedMiddle() {
        Random rnd = new Random(103);
        for (int n : SIZES) {
            // every value shares sign, exponent and top mantissa bits: 1.0 plus noise below 1e-12
            assertMedianIsSortedMiddle(values(n, i -> 1.0 + 1e-12 * rnd.nextDouble()), "1 + 1e-12 U, n " + n);
        }
        for (int n : new int[] {200_001, 1_000_000}) {
            // 90 % in the cluster, the rest far below and above (the range does not narrow it)
            assertMedianIsSortedMiddle(values(n, i -> switch (rnd.nextInt(20)) {
                case 0 -> 1e-3 * rnd.nextDouble();
                case 1 -> 1e3 * (1.0 + rnd.nextDouble());
                default -> 1.0 + 1e-9 * rnd.nextDouble();
            }), "clustered with spread tails, n " + n);
        }
    }

    @Test
    void medianAmongManyExactDuplicatesIsTheSortedMiddle() {
        Random rnd = new Random(104);
        for (int n : SIZES) {
            // seven distinct values, each about 1/7 of n (more than n/8: too many to copy)
            assertMedianIsSortedMiddle(values(n, i -> rnd.nextInt(7) * 0.125), "multiples of 1/8, n " + n);
            // 60 % one value, the rest continuous around it
            assertMedianIsSortedMiddle(values(n, i -> rnd.nextInt(5) < 3 ? 0.25 : 0.5 * rnd.nextDouble()),
                    "60 % at 0.25, n " + n);
        }
    }

    @Test
    void allEqualValuesHaveThatValueAsMedian() {
        for (int n : new int[] {200_001, 200_000}) {
            for (double v : new double[] {0.0, 0.3, Double.MIN_VALUE, Double.MAX_VALUE / 4}) {
                double[] a = new double[n];
                Arrays.fill(a, v);
                // the middle value(s) are all v; 0.5 * (v + v) == v exactly for these v
                assertEquals(v, ErrorStatistics.ofInPlace(a, n).median(), 0.0, "all " + v + ", n " + n);
            }
        }
    }

    @Test
    void zerosAmongPositiveValuesGiveTheSortedMiddle() {
        Random rnd = new Random(105);
        for (int n : SIZES) {
            assertMedianIsSortedMiddle(values(n, i -> rnd.nextInt(3) == 0 ? 0.0 : rnd.nextDouble()),
                    "a third +0.0, n " + n);
            assertMedianIsSortedMiddle(values(n, i -> rnd.nextInt(5) < 3 ? 0.0 : rnd.nextDouble()),
                    "60 % +0.0, n " + n);
        }
    }

    @Test
    void negativeZerosMixedWithZerosAndPositivesGiveTheSortedMiddleValue() {
        Random rnd = new Random(106);
        for (int n : SIZES) {
            double[] a = values(n, i -> switch (rnd.nextInt(4)) {
                case 0 -> -0.0;
                case 1 -> 0.0;
                default -> rnd.nextDouble();
            });
            // -0.0 == 0.0 as values; which zero the middle is depends on the order: compare values
            assertEquals(sortedMiddle(a), ErrorStatistics.ofInPlace(a.clone(), n).median(), 0.0, "n " + n);
            double[] mostlyZeros = values(n, i -> rnd.nextInt(5) < 3 ? (rnd.nextBoolean() ? -0.0 : 0.0)
                    : rnd.nextDouble());
            assertEquals(sortedMiddle(mostlyZeros), ErrorStatistics.ofInPlace(mostlyZeros.clone(), n).median(), 0.0,
                    "60 % zeros of both signs, n " + n);
        }
    }

    @Test
    void subnormalValuesGiveTheSortedMiddle() {
        Random rnd = new Random(107);
        for (int n : SIZES) {
            assertMedianIsSortedMiddle(values(n, i -> Double.MIN_VALUE * rnd.nextInt(1 << 20)), "subnormal, n " + n);
            assertMedianIsSortedMiddle(values(n, i -> rnd.nextBoolean() ? Double.MIN_NORMAL * rnd.nextDouble()
                    : Double.MIN_NORMAL * (1.0 + rnd.nextDouble())), "subnormal and normal, n " + n);
        }
    }

    @Test
    void oneHugeOutlierLeavesTheMedianAtTheSortedMiddle() {
        Random rnd = new Random(108);
        for (double outlier : new double[] {1e300, Double.MAX_VALUE, Double.POSITIVE_INFINITY}) {
            for (int n : new int[] {200_001, 1_000_000}) {
                double[] a = values(n, i -> Math.abs(rnd.nextGaussian()) * 0.05);
                a[rnd.nextInt(n)] = outlier;
                assertMedianIsSortedMiddle(a, "outlier " + outlier + ", n " + n);
            }
        }
    }

    @Test
    void negativeValuesGiveTheSortedMiddle() {
        Random rnd = new Random(109);
        for (int n : SIZES) {
            double[] a = values(n, i -> rnd.nextDouble());
            a[rnd.nextInt(n)] = -1.5;
            assertMedianIsSortedMiddle(a, "one negative, n " + n);
            assertMedianIsSortedMiddle(values(n, i -> rnd.nextGaussian()), "N(0, 1), n " + n);
        }
    }

    @Test
    void lowerMiddleInALowerTopBucketGivesTheMeanOfTheTwoMiddleValues() {
        Random rnd = new Random(110);
        int n = 200_000;
        // half in [1, 1.5] (max exactly 1.5), half in [3, 3.5] (min exactly 3.0), shuffled:
        // the middle values are 1.5 and 3.0, median (1.5 + 3.0) / 2 = 2.25
        double[] a = values(n, i -> i % 2 == 0 ? 1.0 + 0.5 * rnd.nextDouble() : 3.0 + 0.5 * rnd.nextDouble());
        a[0] = 1.5;
        a[1] = 3.0;
        shuffle(a, rnd);
        assertEquals(2.25, ErrorStatistics.ofInPlace(a.clone(), n).median(), 0.0);
        assertMedianIsSortedMiddle(a, "two clusters");
    }

    @Test
    void lowerMiddleInALowerBucketAfterRefiningGivesTheMeanOfTheTwoMiddleValues() {
        Random rnd = new Random(111);
        int n = 400_000;
        // one top bucket holds all: half in [1, 1 + 1e-7], half in [1.001, 1.001 + 1e-7]; the
        // middle values (exact members) are 1 + 1e-7 and 1.001: told apart only after refining
        double lowTop = 1.0 + 1e-7;
        double highBottom = 1.001;
        double[] a = values(n, i -> i % 2 == 0 ? 1.0 + 1e-7 * rnd.nextDouble() : highBottom + 1e-7 * rnd.nextDouble());
        a[0] = lowTop;
        a[1] = highBottom;
        shuffle(a, rnd);
        assertEquals(0.5 * (lowTop + highBottom), ErrorStatistics.ofInPlace(a.clone(), n).median(), 0.0);
        assertMedianIsSortedMiddle(a, "two close clusters");
    }

    @Test
    void twoRepeatedValuesUlpsApartGiveTheirMeanForEvenCount() {
        int n = 200_000;
        double low = 1.0;
        double high = 1.0 + 100 * Math.ulp(1.0);
        // n/2 copies of each: the middle values are low and high; their mean is 1 + 50 ulp exactly
        double[] a = values(n, i -> i % 2 == 0 ? low : high);
        assertEquals(1.0 + 50 * Math.ulp(1.0), ErrorStatistics.ofInPlace(a.clone(), n).median(), 0.0);
        double[] odd = values(n + 1, i -> i % 2 == 0 ? low : high); // one more low: the middle is low
        assertEquals(low, ErrorStatistics.ofInPlace(odd, n + 1).median(), 0.0);
    }

    @Test
    void otherStatisticsAreTheIndexOrderSumsOfTheDefinitions() {
        Random rnd = new Random(112);
        double[][] inputs = {
            values(1_000_000, i -> Math.abs(rnd.nextGaussian()) * 0.05),
            values(200_001, i -> 1.0 + 1e-9 * rnd.nextDouble()),
            values(200_000, i -> rnd.nextInt(7) * 0.125),
            values(100_000, i -> rnd.nextGaussian()),
            values(1_000, i -> rnd.nextDouble()),
        };
        for (double[] a : inputs) {
            int n = a.length;
            double sum = 0.0;
            double sse = 0.0;
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (double v : a) {
                sum += v;
                sse += v * v;
                min = Math.min(min, v);
                max = Math.max(max, v);
            }
            double mean = sum / n;
            double sq = 0.0;
            for (double v : a) {
                sq += (v - mean) * (v - mean);
            }
            ErrorStatistics s = ErrorStatistics.ofInPlace(a.clone(), n);
            String where = "n " + n;
            assertBitsEqual(mean, s.mean(), "mean " + where);
            assertBitsEqual(sse, s.sse(), "sse " + where);
            assertBitsEqual(Math.sqrt(sse / n), s.rmse(), "rmse " + where);
            assertBitsEqual(Math.sqrt(sq / n), s.std(), "std " + where);
            assertBitsEqual(min, s.min(), "min " + where);
            assertBitsEqual(max, s.max(), "max " + where);
            assertEquals(n, s.n());
            assertEquals(ErrorStatistics.of(a), s, "copying and in-place agree, " + where);
        }
    }

    private static void assertMedianIsSortedMiddle(double[] a, String what) {
        double expected = sortedMiddle(a);
        assertBitsEqual(expected, ErrorStatistics.ofInPlace(a.clone(), a.length).median(), what);
        assertBitsEqual(expected, Selection.median(a.clone(), a.length), what + " (Selection.median)");
    }
}
