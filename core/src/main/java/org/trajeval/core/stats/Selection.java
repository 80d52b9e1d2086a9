package org.trajeval.core.stats;

/**
 * Order statistics. Non-negative values (errors) are selected by radix on their IEEE bits, which
 * order like the values for +0.0 and up: two or three linear passes of 65 536-bucket histograms,
 * no reordering. Anything else falls back to Hoare's quickselect (in place).
 */
final class Selection {
    private static final int RADIX_BITS = 16;
    private static final int BUCKETS = 1 << RADIX_BITS;
    private static final int SMALL = 4096;

    private Selection() {
    }

    /**
     * @return the median of {@code a[0..n)}: the middle value, or the mean of the two middle
     *     values for even n; non-negative input is left untouched, other input may be reordered
     */
    static double median(double[] a, int n) {
        boolean nonNegative = true;
        for (int i = 0; i < n && nonNegative; i++) {
            nonNegative = a[i] >= 0.0 && Double.doubleToRawLongBits(a[i]) >= 0L;
        }
        if (!nonNegative || n <= SMALL) {
            return medianBySwapping(a, n);
        }
        int k = n / 2;
        double[] pair = radixSelectWithPredecessor(a, n, k);
        return n % 2 == 1 ? pair[1] : 0.5 * (pair[0] + pair[1]);
    }

    /**
     * {k-1-th, k-th} smallest (0-based, k >= 1) of non-negative values in one radix descent: the
     * predecessor is usually among the last candidates; otherwise it is the largest value below
     * them (one more pass).
     */
    static double[] radixSelectWithPredecessor(double[] a, int n, int k) {
        long prefix = 0L;
        int shift = 64;
        int rank = k;
        int candidates = n;
        int[] count = new int[BUCKETS];
        while (candidates > SMALL && shift > 0) {
            shift -= RADIX_BITS;
            java.util.Arrays.fill(count, 0);
            long mask = shift + RADIX_BITS >= 64 ? 0L : (-1L << (shift + RADIX_BITS));
            for (int i = 0; i < n; i++) {
                long bits = Double.doubleToRawLongBits(a[i]);
                if ((bits & mask) == prefix) {
                    count[(int) ((bits >>> shift) & (BUCKETS - 1))]++;
                }
            }
            int digit = 0;
            while (rank >= count[digit]) {
                rank -= count[digit];
                digit++;
            }
            prefix |= ((long) digit) << shift;
            candidates = count[digit];
        }
        long mask = shift >= 64 ? 0L : (-1L << shift);
        double[] rest = new double[candidates];
        int m = 0;
        for (int i = 0; i < n && m < candidates; i++) {
            if ((Double.doubleToRawLongBits(a[i]) & mask) == prefix) {
                rest[m++] = a[i];
            }
        }
        java.util.Arrays.sort(rest, 0, m);
        double kth = rest[rank];
        if (rank > 0) {
            return new double[] {rest[rank - 1], kth};
        }
        // the predecessor lies below the candidates' range: the largest value with smaller bits
        double below = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            if ((Double.doubleToRawLongBits(a[i]) & mask) < prefix) {
                below = Math.max(below, a[i]);
            }
        }
        return new double[] {below, kth};
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
