package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import java.util.Random;
import java.util.function.IntToDoubleFunction;

/**
 * What the median tests share: the reference median (the middle of the values sorted by
 * {@link Arrays#sort}, 0.5 * (lower + upper) for even n), a bitwise comparison, and generated inputs.
 */
final class MedianCases {
    private MedianCases() {
    }

    /** @return the middle of {@code a} sorted (a is not changed) */
    static double sortedMiddle(double[] a) {
        double[] sorted = a.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        return n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
    }

    /** Asserts the two doubles have the same bits (so -0.0 differs from 0.0). */
    static void assertBitsEqual(double expected, double actual, String what) {
        assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual),
                what + ": expected " + expected + ", got " + actual);
    }

    /** @return {@code value(0), ..., value(n - 1)} */
    static double[] values(int n, IntToDoubleFunction value) {
        double[] a = new double[n];
        for (int i = 0; i < n; i++) {
            a[i] = value.applyAsDouble(i);
        }
        return a;
    }

    /** Shuffles {@code a} in place (Fisher-Yates). */
    static void shuffle(double[] a, Random rnd) {
        for (int i = a.length - 1; i > 0; i--) {
            int j = rnd.nextInt(i + 1);
            double t = a[i];
            a[i] = a[j];
            a[j] = t;
        }
    }
}
