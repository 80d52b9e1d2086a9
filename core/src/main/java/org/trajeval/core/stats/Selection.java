package org.trajeval.core.stats;

/**
 * Order statistics. Large non-negative inputs (errors) are narrowed by radix on their IEEE bits
 * ({@link RadixMedian}, no reordering); anything else by Hoare's quickselect (in place).
 */
final class Selection {
    private Selection() {
    }

    /**
     * @return the median of {@code a[0..n)}: the middle value, or the mean of the two middle
     *     values for even n; large non-negative input is left untouched, other input may be
     *     reordered
     */
    static double median(double[] a, int n) {
        if (n < RadixMedian.MIN_COUNT) {
            return medianBySwapping(a, n);
        }
        int[] top = new int[RadixMedian.TOP_BUCKETS];
        for (int i = 0; i < n; i++) {
            top[(int) (Double.doubleToRawLongBits(a[i]) >>> RadixMedian.TOP_SHIFT)]++;
        }
        // 0 and +infinity bound every value the radix path accepts
        ValueChunks values = ValueChunks.of(a, n);
        RadixMedian radix = RadixMedian.start(top, values, n, 0.0, Double.POSITIVE_INFINITY);
        if (radix == null) {
            return medianBySwapping(a, n);
        }
        while (!radix.done()) {
            radix.nextPass(values, 0.0);
        }
        return radix.median();
    }

    /** The median by quickselect; reorders the array. */
    static double medianBySwapping(double[] a, int n) {
        int k = n / 2;
        double upper = select(a, 0, n - 1, k);
        if (n % 2 == 1) {
            return upper;
        }
        // a[0..k) now holds the k smallest values: the lower middle is their maximum
        double lower = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < k; i++) {
            lower = Math.max(lower, a[i]);
        }
        return 0.5 * (lower + upper);
    }

    /** Places the k-th smallest value at a[k], smaller ones before it, and returns it. */
    static double select(double[] a, int lo, int hi, int k) {
        while (hi > lo) {
            int mid = (lo + hi) >>> 1;
            // median of three as pivot
            if (a[mid] < a[lo]) {
                swap(a, mid, lo);
            }
            if (a[hi] < a[lo]) {
                swap(a, hi, lo);
            }
            if (a[hi] < a[mid]) {
                swap(a, hi, mid);
            }
            double pivot = a[mid];
            int i = lo;
            int j = hi;
            while (i <= j) {
                while (a[i] < pivot) {
                    i++;
                }
                while (a[j] > pivot) {
                    j--;
                }
                if (i <= j) {
                    swap(a, i, j);
                    i++;
                    j--;
                }
            }
            if (k <= j) {
                hi = j;
            } else if (k >= i) {
                lo = i;
            } else {
                return a[k];
            }
        }
        return a[k];
    }

    private static void swap(double[] a, int i, int j) {
        double t = a[i];
        a[i] = a[j];
        a[j] = t;
    }
}
