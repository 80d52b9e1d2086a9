package org.trajeval.core.stats;

/**
 * The exact median of non-negative values (+0.0 up to +infinity, no NaN, no -0.0) found by
 * narrowing on their raw IEEE bits, which order like the values in that range.
 *
 * <p>The caller builds a histogram of the top {@value #TOP_BITS} bits (sign, 11 exponent bits and
 * 6 mantissa bits: 64 buckets per binade) in a pass it makes anyway ({@link ErrorStatistics} does it
 * while summing) and hands it to {@link #start}. That picks the bucket holding rank k = n/2 (and
 * k-1 for even n) and fixes further the bits that the bucket's bounds clipped to [min, max]
 * share (all values equal: no further pass at all). Each {@link #nextPass} then reads the values
 * once in index order and, in the same loop, returns sum (a_i - mean)^2 so the caller's deviation
 * pass costs nothing extra:
 * <ul>
 *   <li>usually the median bucket is small (for errors shaped like |N(0, s)| about 0.6 % of n):
 *       its values are copied to a small array and the middle value(s) selected there, so the
 *       whole median costs no full pass beyond the two the statistics need;</li>
 *   <li>if the bucket holds more than max({@value #SMALL_COPY}, n/8) values (values clustered in
 *       one 1/64 of a binade, many exact duplicates, all values equal) a copy would cost up to
 *       8 n bytes, so instead the pass histograms the next 16 bits of the bucket's values; at most
 *       three such passes fix the remaining 46 bits. The copy is therefore at most
 *       max(32 KiB, n) bytes.</li>
 * </ul>
 * For even n, when rank k-1 lies in a lower bucket than rank k it is the largest value of the
 * highest non-empty bucket below, tracked in the next pass (one extra pass when the last refining
 * pass left all candidates equal). Worst case: the caller's pass and four more.
 *
 * <p>Memory: the 2^18-entry int histogram (1 MiB), one 64 KiB histogram per refining pass, the
 * copy above. Not thread-safe (one instance per median); no static mutable state.
 */
final class RadixMedian {
    /**
     * Fewest values worth the 1 MiB histogram. Measured on 2 shared EPYC cores, |N(0, 0.05)|
     * values, median only: quickselect 115 us vs radix 154 us at 32 768 values (about even, the
     * radix figure with its own histogram pass), 528 us vs 202 us at 49 152.
     */
    static final int MIN_COUNT = 1 << 15;
    /** Width of the caller's first histogram digit: sign bit, 11 exponent bits, 6 mantissa bits. */
    static final int TOP_BITS = 18;
    /** Bucket of value bits b in the first histogram: {@code (int) (b >>> TOP_SHIFT)}. */
    static final int TOP_SHIFT = 64 - TOP_BITS;
    /** Number of buckets of the first histogram. */
    static final int TOP_BUCKETS = 1 << TOP_BITS;
    private static final int REFINE_BITS = 16;
    private static final int SMALL_COPY = 4096;
    private static final long INFINITY_BITS = Double.doubleToRawLongBits(Double.POSITIVE_INFINITY);
    /** A prefix no non-negative value's bits match (their sign bit is 0), under any mask. */
    private static final long NONE = -1L;

    private final int n;
    private final boolean even;
    /** The candidates: values whose bits b satisfy (b &amp; mask) == prefix, mask = -1 &lt;&lt; shift. */
    private long prefix;
    private int shift;
    private long mask;
    /** Rank of the k-th smallest value among the candidates (0-based). */
    private int rank;
    private int candidates;
    /** Even n only: the set holding rank k-1 when it is not among the candidates; its maximum is k-1. */
    private long predecessorPrefix = NONE;
    private long predecessorMask = -1L;
    private boolean predecessorOutside;
    private double below = Double.NEGATIVE_INFINITY;
    private double median = Double.NaN;
    private boolean done;

    private RadixMedian(int n) {
        this.n = n;
        this.even = n % 2 == 0;
    }

    /**
     * @param top the histogram of {@code (int) (bits >>> TOP_SHIFT)} over the raw bits of
     *     {@code a[0..n)}, length {@link #TOP_BUCKETS}
     * @param values the values (read only when the histogram shows +infinity or NaN, to tell them apart)
     * @param n the number of values, at least 2
     * @param min the smallest of the values (any bound at or below it is correct, just slower)
     * @param max the largest of the values (any bound at or above it is correct, just slower)
     * @return the narrowing started on the bucket of the median, or null when some value is
     *     negative (sign bit set, including -0.0) or NaN: then this method does not apply
     */
    static RadixMedian start(int[] top, ValueChunks values, int n, double min, double max) {
        int infinityBucket = (int) (INFINITY_BITS >>> TOP_SHIFT);
        for (int b = infinityBucket + 1; b < top.length; b++) {
            if (top[b] != 0) {
                return null; // NaN with high mantissa bits, or a sign bit
            }
        }
        if (top[infinityBucket] != 0) {
            boolean[] nan = new boolean[1];
            values.forEach((a, len) -> {
                for (int i = 0; i < len; i++) {
                    nan[0] |= Double.isNaN(a[i]);
                }
            });
            if (nan[0]) {
                return null;
            }
        }
        RadixMedian m = new RadixMedian(n);
        m.shift = TOP_SHIFT;
        m.mask = -1L << TOP_SHIFT;
        m.rank = n / 2;
        m.descend(top);
        m.narrowToRange(Double.doubleToRawLongBits(min), Double.doubleToRawLongBits(max));
        return m;
    }

    /** @return true once {@link #median()} is known */
    boolean done() {
        return done;
    }

    /** @return the median: the middle value, or 0.5 * (a + b) of the two middle values for even n */
    double median() {
        if (!done) {
            throw new IllegalStateException("median not narrowed down yet");
        }
        return median;
    }

    /**
     * Reads the values once in index order, narrowing the candidates (or copying them and
     * finishing), and in the same loop sums the squared deviations from {@code mean}.
     *
     * @return sum over i in index order of (a_i - mean)^2
     */
    double nextPass(ValueChunks a, double mean) {
        if (done) {
            throw new IllegalStateException("median already known");
        }
        if (shift == 0) {
            return lastPassAllCandidatesEqual(a, mean);
        }
        if (candidates <= Math.max(SMALL_COPY, n >>> 3)) {
            return copyPass(a, mean);
        }
        return refinePass(a, mean);
    }

    /** Picks the digit holding rank {@link #rank} in {@code count} (digits below {@link #shift}). */
    private void descend(int[] count) {
        int digit = 0;
        while (rank >= count[digit]) {
            rank -= count[digit];
            digit++;
        }
        candidates = count[digit];
        if (even && rank == 0 && !predecessorOutside) {
            // rank k-1 is the largest value of the highest non-empty bucket below this one
            int lower = digit - 1;
            while (count[lower] == 0) {
                lower--;
            }
            predecessorPrefix = prefix | ((long) lower << shift);
            predecessorMask = mask;
            predecessorOutside = true;
        }
        prefix |= (long) digit << shift;
    }

    /**
     * The candidates' bits lie in [max(prefix, lo), min(prefix | ~mask, hi)]: the bits those two
     * bounds share are fixed too (clustered values: e.g. 1.0 plus noise of 1e-12 skips 34 bits).
     */
    private void narrowToRange(long lo, long hi) {
        long low = Math.max(prefix, lo);
        long high = Math.min(prefix | ~mask, hi);
        int common = Long.numberOfLeadingZeros(low ^ high); // 64 when low == high
        if (64 - common < shift) {
            shift = 64 - common;
            mask = -1L << shift;
            prefix = low & mask;
        }
        if (shift == 0 && predecessorPrefix == NONE) {
            finishWithEqualCandidates(below);
        }
    }

    private double refinePass(ValueChunks values, double mean) {
        int newShift = Math.max(0, shift - REFINE_BITS);
        int digitMask = (1 << (shift - newShift)) - 1;
        int[] count = new int[digitMask + 1];
        long pm = mask;
        long pp = prefix;
        long qm = predecessorMask;
        long qp = predecessorPrefix;
        double[] state = {0.0, below}; // sum of squared deviations, largest value of the predecessor set
        values.forEach((a, len) -> {
            double sq = state[0];
            double lowerMax = state[1];
            for (int i = 0; i < len; i++) {
                double v = a[i];
                double d = v - mean;
                sq += d * d;
                long bits = Double.doubleToRawLongBits(v);
                if ((bits & pm) == pp) {
                    count[(int) (bits >>> newShift) & digitMask]++;
                } else if ((bits & qm) == qp) {
                    lowerMax = Math.max(lowerMax, v);
                }
            }
            state[0] = sq;
            state[1] = lowerMax;
        });
        below = state[1];
        predecessorPrefix = NONE; // resolved (if it was pending)
        shift = newShift;
        mask = -1L << newShift;
        descend(count);
        if (shift == 0 && predecessorPrefix == NONE) {
            finishWithEqualCandidates(below);
        }
        return state[0];
    }

    private double copyPass(ValueChunks values, double mean) {
        double[] copy = new double[candidates];
        long pm = mask;
        long pp = prefix;
        long qm = predecessorMask;
        long qp = predecessorPrefix;
        double[] state = {0.0, below}; // sum of squared deviations, largest value of the predecessor set
        int[] copied = {0};
        values.forEach((a, len) -> {
            double sq = state[0];
            double lowerMax = state[1];
            int k = copied[0];
            for (int i = 0; i < len; i++) {
                double v = a[i];
                double d = v - mean;
                sq += d * d;
                long bits = Double.doubleToRawLongBits(v);
                if ((bits & pm) == pp) {
                    copy[k++] = v;
                } else if ((bits & qm) == qp) {
                    lowerMax = Math.max(lowerMax, v);
                }
            }
            state[0] = sq;
            state[1] = lowerMax;
            copied[0] = k;
        });
        int m = copied[0];
        double lowerMax = state[1];
        double sq = state[0];
        double upper = Selection.select(copy, 0, m - 1, rank);
        if (!even) {
            median = upper;
        } else if (rank > 0) {
            // copy[0..rank) now holds the candidates below rank: the lower middle is their maximum
            double lower = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < rank; i++) {
                lower = Math.max(lower, copy[i]);
            }
            median = 0.5 * (lower + upper);
        } else {
            median = 0.5 * (lowerMax + upper);
        }
        done = true;
        return sq;
    }

    /** All 64 bits are fixed: every candidate equals one value; a pending predecessor is left. */
    private double lastPassAllCandidatesEqual(ValueChunks values, double mean) {
        long qm = predecessorMask;
        long qp = predecessorPrefix;
        double[] state = {0.0, below}; // sum of squared deviations, largest value of the predecessor set
        values.forEach((a, len) -> {
            double sq = state[0];
            double lowerMax = state[1];
            for (int i = 0; i < len; i++) {
                double v = a[i];
                double d = v - mean;
                sq += d * d;
                if ((Double.doubleToRawLongBits(v) & qm) == qp) {
                    lowerMax = Math.max(lowerMax, v);
                }
            }
            state[0] = sq;
            state[1] = lowerMax;
        });
        finishWithEqualCandidates(state[1]);
        return state[0];
    }

    private void finishWithEqualCandidates(double lowerMax) {
        double upper = Double.longBitsToDouble(prefix);
        if (!even) {
            median = upper;
        } else {
            median = 0.5 * ((rank > 0 ? upper : lowerMax) + upper);
        }
        done = true;
    }
}
