package org.trajeval.core.stats;

/**
 * The exact median of a few thousand non-negative values (+0.0 up to +infinity, no NaN, no -0.0),
 * for counts below {@link RadixMedian#MIN_COUNT}: one histogram of the values' raw IEEE bits
 * (which order like the values in that range) over [min, max], then quickselect on a copy of the
 * few values in the median's buckets only.
 *
 * <p>Bucket of value v: its sign, exponent and top {@value #MANTISSA_BITS} mantissa bits (64
 * buckets per binade, as {@link RadixMedian}'s first digit) counted down from those of max, the
 * {@value #BUCKETS} buckets covering the 32 binades below max (8 KiB of counts); values further
 * below, zeros included, share the lowest bucket. The caller counts each value
 * ({@link #count}) in a pass it makes anyway ({@link ErrorStatistics} does it while summing the
 * squared deviations); {@link #median} then reads the values once more and copies those in the
 * buckets of ranks k - 1 (even n only) and k, k = n / 2 (for errors shaped like |N(0, s)| at
 * n = 10^4 a few dozen values), and selects there: upper = the value of rank k, lower (even n) =
 * the largest of the values below it, median = upper, or 0.5 (lower + upper) for even n. These are
 * the values and the one operation of {@link Selection#medianBySwapping}, so the bits are the
 * same. Quickselect over all n values costs about 15 ns per value here (its comparisons are
 * unpredictable branches); the histogram and copy passes are predictable. Worst case (all values
 * in one bucket, e.g. all equal, or more than half of them zero): the copy holds every value, as
 * the quickselect path's copy does.
 *
 * <p>Not thread-safe (one instance per median); no static mutable state.
 */
final class BucketMedian {
    /** Fewest values for which the histogram pays off against quickselect on all values. */
    static final int MIN_COUNT = 1024;
    /** Number of buckets (a power of two). */
    static final int BUCKETS = 1 << 11;
    /** Mantissa bits in a bucket's key. */
    static final int MANTISSA_BITS = 6;
    private static final int KEY_SHIFT = 52 - MANTISSA_BITS;

    /** Key of max's bucket minus (BUCKETS - 1): a value's bucket is its key minus this, at least 0. */
    private final int base;
    private final int[] counts = new int[BUCKETS];

    private BucketMedian(int base) {
        this.base = base;
    }

    /**
     * @param min the smallest of the values
     * @param max the largest of the values
     * @return an empty histogram for values in [min, max], or null when they are not all in
     *     [+0.0, +infinity] (min negative or -0.0, or either NaN): then this method does not apply
     */
    static BucketMedian over(double min, double max) {
        if (Double.doubleToRawLongBits(min) < 0 || Double.isNaN(min) || Double.isNaN(max)) {
            return null;
        }
        return new BucketMedian(key(max) - (BUCKETS - 1));
    }

    /** @return the sign, exponent and top mantissa bits of a non-negative value */
    private static int key(double v) {
        return (int) (Double.doubleToRawLongBits(v) >>> KEY_SHIFT);
    }

    /** Counts value v, which lies in [min, max] of {@link #over}. */
    void count(double v) {
        counts[bucket(v)]++;
    }

    private int bucket(double v) {
        return Math.max(0, key(v) - base);
    }

    /**
     * @param values the n values counted, every one of them once, read again in index order
     * @return their median: the middle value, or 0.5 * (lower + upper) of the two middle values for even n
     */
    double median(ValueChunks values) {
        int n = values.size();
        int k = n / 2;
        int lowRank = n % 2 == 0 ? k - 1 : k;
        int first = -1; // bucket of rank lowRank
        int below = 0; // values in buckets before first
        int seen = 0;
        int last = 0; // bucket of rank k
        for (int b = 0; b < BUCKETS; b++) {
            int next = seen + counts[b];
            if (first < 0 && lowRank < next) {
                first = b;
                below = seen;
            }
            if (k < next) {
                last = b;
                seen = next;
                break;
            }
            seen = next;
        }
        double[] copy = new double[seen - below];
        int from = first;
        int width = last - first;
        int[] filled = {0};
        values.forEach((a, len) -> {
            int c = filled[0];
            for (int i = 0; i < len; i++) {
                double v = a[i];
                // from <= bucket <= last as one unsigned comparison: two would be a branch taken for
                // about half the values at random (a misprediction each)
                if (Integer.compareUnsigned(bucket(v) - from, width) <= 0) {
                    copy[c++] = v;
                }
            }
            filled[0] = c;
        });
        int rank = k - below;
        double upper = Selection.select(copy, 0, copy.length - 1, rank);
        if (n % 2 == 1) {
            return upper;
        }
        // copy[0..rank) now holds the copy's rank smallest values: the lower middle is their maximum
        double lower = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < rank; i++) {
            lower = Math.max(lower, copy[i]);
        }
        return 0.5 * (lower + upper);
    }
}
