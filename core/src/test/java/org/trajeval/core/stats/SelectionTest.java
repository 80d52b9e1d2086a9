package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Medians by selection must equal the median of the sorted values exactly. */
class SelectionTest {
    @Test
    void medianEqualsTheSortedMiddleForManySeededInputs() {
        Random rnd = new Random(11);
        for (int trial = 0; trial < 60; trial++) {
            int n = 1 + rnd.nextInt(trial < 30 ? 50 : 60_000);
            double[] a = new double[n];
            for (int i = 0; i < n; i++) {
                // errors: mostly continuous, some repeated values and exact zeros
                a[i] = switch (rnd.nextInt(5)) {
                    case 0 -> 0.0;
                    case 1 -> 0.25;
                    default -> Math.abs(rnd.nextGaussian()) * Math.pow(10, rnd.nextInt(6) - 3);
                };
            }
            if (trial % 7 == 0) {
                a[0] = -1.5; // a negative value takes the swapping path
            }
            double[] sorted = a.clone();
            Arrays.sort(sorted);
            double expected = n % 2 == 1 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
            assertEquals(expected, Selection.median(a.clone(), n), 0.0, "trial " + trial + " n " + n);
        }
    }

    @Test
    void inPlaceStatisticsEqualTheCopyingOnesBitForBit() {
        Random rnd = new Random(5);
        double[] a = new double[100_001];
        for (int i = 0; i < a.length; i++) {
            a[i] = Math.abs(rnd.nextGaussian());
        }
        assertEquals(ErrorStatistics.of(a), ErrorStatistics.ofInPlace(a.clone(), a.length));
    }
}
