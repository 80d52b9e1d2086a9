package org.trajeval.core.io;

import java.util.Arrays;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Growing primitive columns of poses (column 0 is the timestamp in s) with the timestamp-order
 * policy: with {@link TimestampOrder#REFUSE_UNSORTED} each timestamp is checked against the one
 * before as it is added; with {@link TimestampOrder#SORT} the poses are sorted stably by time at
 * the end and any two equal timestamps are refused, naming both lines (or kept in file order
 * with {@link DuplicateTimestamps#KEEP}).
 */
final class PoseBuffer {
    /** {@link #add} result: the pose was taken. */
    static final int ACCEPTED = 0;
    /** {@link #add} result: the timestamp is smaller than the one before (nothing was added). */
    static final int DECREASING = 1;
    /** {@link #add} result: the timestamp equals the one before (nothing was added). */
    static final int DUPLICATE = 2;

    private static final int INITIAL_CAPACITY = 1024;
    /**
     * Largest accepted |position| (m): 1e9 m is 2.6 times the Moon's distance, which no robot
     * needs, and keeps every squared error and sum of squares far from overflow (1e18 per pose).
     */
    static final double MAX_POSITION_M = 1e9;
    private static final String[] NO_NAMES = {};

    private final String source;
    private final String timeColumn;
    private final TimestampOrder order;
    private final long maxPoses;
    private final double[][] columns;
    private long[] lines;
    private int n;
    private double lastT = Double.NaN;
    private long lastLine;
    private ByteLines progress;
    private final boolean keepDuplicates;
    private String[] positionNames = NO_NAMES;

    /**
     * @param source file name for messages
     * @param timeColumn name of the time column for messages
     * @param columnCount number of columns, the time included
     */
    PoseBuffer(String source, String timeColumn, int columnCount, TimestampOrder order, long maxPoses) {
        this(source, timeColumn, columnCount, order, DuplicateTimestamps.REFUSE, maxPoses);
    }

    /** As above, with a duplicate-timestamp policy. */
    PoseBuffer(String source, String timeColumn, int columnCount, TimestampOrder order, DuplicateTimestamps duplicates,
            long maxPoses) {
        this.keepDuplicates = duplicates == DuplicateTimestamps.KEEP;
        this.source = source;
        this.timeColumn = timeColumn;
        this.order = order;
        this.maxPoses = Math.min(maxPoses, Integer.MAX_VALUE - 8);
        this.columns = new double[columnCount][INITIAL_CAPACITY];
        this.lines = order == TimestampOrder.SORT ? new long[INITIAL_CAPACITY] : null;
    }

    /**
     * Appends one pose; {@code row[0]} is its time (s), {@code row[c]} the value of column c.
     *
     * @return {@link #ACCEPTED}, or (only when refusing unsorted input) {@link #DECREASING} or
     *     {@link #DUPLICATE}, in which case {@link #orderProblem} builds the refusal
     * @throws InputException when the pose limit is exceeded
     */
    int add(double[] row, long line) {
        checkPositions(row, line);
        int i = place(row[0], line);
        if (i < 0) {
            return -i;
        }
        for (int c = 0; c < columns.length; c++) {
            columns[c][i] = row[c];
        }
        return ACCEPTED;
    }

    /**
     * The first step of {@link #add}: refuses a position beyond {@link #MAX_POSITION_M}, the
     * positions being {@code row[1]}, {@code row[2]}, ... (as many as {@link #positions} named).
     *
     * @throws InputException {@link InputProblem#OUT_OF_RANGE} for the first such position
     */
    void checkPositions(double[] row, long line) {
        for (int c = 0; c < positionNames.length; c++) {
            if (!(Math.abs(row[c + 1]) <= MAX_POSITION_M)) {
                throw new InputException(source, line, positionNames[c], InputProblem.OUT_OF_RANGE,
                        "column '" + positionNames[c] + "' must be a position (m) within +-1e9 m",
                        Double.toString(row[c + 1]));
            }
        }
    }

    /**
     * The second step of {@link #add}, for a reader that stores a pose's values itself (in another
     * order than it read them): checks the timestamp {@code t} (s) against the one before and makes
     * room for one more pose. The caller then stores every column's value at the index returned,
     * in {@link #liveColumns()} fetched after this call (a growth replaces the columns), before the
     * next call.
     *
     * @return the pose's index, or (only when refusing unsorted input) {@code -DECREASING} or
     *     {@code -DUPLICATE}, nothing taken, for {@link #orderProblem}
     * @throws InputException when the pose limit is exceeded
     */
    int place(double t, long line) {
        if (lines == null && n > 0 && !(t > lastT) && !(keepDuplicates && t == lastT)) {
            return t < lastT ? -DECREASING : -DUPLICATE;
        }
        if (n == columns[0].length || n >= maxPoses) {
            grow(line);
        }
        final int i = n;
        if (lines != null) {
            lines[i] = line;
        }
        n = i + 1;
        lastT = t;
        lastLine = line;
        return i;
    }

    /** @return the columns themselves, not a copy, for {@link #place} (valid until the next {@link #place} or {@link #add}) */
    double[][] liveColumns() {
        return columns;
    }

    /**
     * Bounds the positions: columns 1, 2, ... (named {@code names} in messages) must lie within
     * {@link #MAX_POSITION_M}; {@link #add} refuses a pose beyond it with {@link InputProblem#OUT_OF_RANGE}.
     *
     * @return this buffer
     */
    PoseBuffer positions(String... names) {
        this.positionNames = names.clone();
        return this;
    }

    /**
     * Sizes the columns for a pose count known in advance (a KITTI times file has one line per pose
     * already read): up to that many poses need no growth, and {@link #finish} hands exactly that
     * many over without a trimming copy. Call before the first {@link #add}.
     *
     * @return this buffer
     */
    PoseBuffer capacity(int poses) {
        if (n > 0) {
            throw new IllegalStateException("capacity is set before the first pose");
        }
        int c = Math.max(1, poses);
        for (int k = 0; k < columns.length; k++) {
            columns[k] = new double[c];
        }
        if (lines != null) {
            lines = new long[c];
        }
        return this;
    }

    /**
     * Takes over columns of an earlier buffer whose poses are no longer needed (a block's segment
     * already copied, {@link BlockRead}) instead of the initial ones. Call before the first {@link #add}.
     *
     * @return this buffer
     */
    PoseBuffer reuse(double[][] spare) {
        if (n > 0 || spare.length != columns.length || lines != null) {
            throw new IllegalStateException("columns are reused before the first pose, by a buffer of as many columns");
        }
        System.arraycopy(spare, 0, columns, 0, columns.length);
        return this;
    }

    /** @return the columns themselves (for {@link #reuse} by a later buffer once this one's poses are copied) */
    double[][] columns() {
        return columns.clone();
    }

    /**
     * Lets the buffer size itself from the bytes read so far: at the first growth it extrapolates
     * the pose count from the bytes per pose, so a big file needs one allocation, not twenty.
     */
    void sizeFrom(ByteLines lines) {
        this.progress = lines;
    }

    private void grow(long line) {
        if (n >= maxPoses) {
            throw FileProblems.tooManyPoses(source, line, maxPoses);
        }
        long wanted = (long) n * 2;
        if (progress != null && progress.expectedBytes() > 0 && progress.consumedBytes() > 0) {
            // bytes per pose: sampled over the whole file when it is big, else from the first lines
            double sampled = progress.sampledBytesPerLine();
            double bytesPerPose = sampled > 0 ? sampled : (double) progress.consumedBytes() / n;
            long estimate = (long) (progress.expectedBytes() / bytesPerPose * 1.02) + 64;
            wanted = Math.max(estimate, n + (n >> 3) + 64);
        }
        int capacity = (int) Math.min(wanted, maxPoses);
        for (int c = 0; c < columns.length; c++) {
            columns[c] = Arrays.copyOf(columns[c], capacity);
        }
        if (lines != null) {
            lines = Arrays.copyOf(lines, capacity);
        }
    }

    /** @return number of poses so far */
    int size() {
        return n;
    }

    /** @return column {@code c}: its first {@link #size()} values are the poses' (the array, not a copy) */
    double[] column(int c) {
        return columns[c];
    }

    /** @return value of column {@code c} of pose {@code i} */
    double get(int c, int i) {
        return columns[c][i];
    }

    /**
     * The refusal for an {@link #add} result other than {@link #ACCEPTED}.
     *
     * @param found the timestamp as written in the file
     */
    InputException orderProblem(int code, double t, long line, String found) {
        if (code == DECREASING) {
            return new InputException(source, line, timeColumn, InputProblem.DECREASING_TIMESTAMP,
                    "column '" + timeColumn + "' must be after line " + lastLine + " (" + lastT
                            + " s): timestamps must increase. Sort the file, or pass --sort",
                    found);
        }
        return duplicate(lastLine, line, t, found);
    }

    private InputException duplicate(long firstLine, long line, double t, String found) {
        return new InputException(source, line, timeColumn, InputProblem.DUPLICATE_TIMESTAMP,
                "column '" + timeColumn + "' repeats the timestamp of line " + firstLine + " (" + t
                        + " s): timestamps must be unique (--sort does not remove duplicates; --duplicates keep keeps both"
                        + " poses, as evo does)",
                found);
    }

    /**
     * Ends the reading: refuses an empty buffer, sorts when asked (refusing duplicates) and
     * returns the columns trimmed to the pose count.
     *
     * @param emptyWhat what the file held instead of poses, for the EMPTY message
     */
    double[][] finish(String emptyWhat) {
        if (n == 0) {
            throw FileProblems.empty(source, emptyWhat);
        }
        double[][] out = new double[columns.length][];
        if (lines != null && !increasing(columns[0], n, keepDuplicates)) {
            int[] perm = stableOrder(columns[0], n);
            for (int c = 0; c < columns.length; c++) {
                double[] src = columns[c];
                double[] dst = new double[n];
                for (int i = 0; i < n; i++) {
                    dst[i] = src[perm[i]];
                }
                out[c] = dst;
            }
            double[] t = out[0];
            for (int i = 1; i < n && !keepDuplicates; i++) {
                if (t[i] == t[i - 1]) {
                    long a = lines[perm[i - 1]];
                    long b = lines[perm[i]];
                    throw duplicate(Math.min(a, b), Math.max(a, b), t[i], Double.toString(t[i]));
                }
            }
            return out;
        }
        for (int c = 0; c < columns.length; c++) {
            out[c] = columns[c].length == n ? columns[c] : Arrays.copyOf(columns[c], n);
        }
        return out;
    }

    /**
     * As {@link #finish} but trimming only when it is worth a copy: the columns may be longer than
     * {@link #size()} by at most 4 % (only the first {@link #size()} values are poses). The size
     * is estimated from line lengths sampled over the whole file; when that still overshoots by
     * more, the columns are copied one at a time.
     */
    double[][] finishUntrimmed(String emptyWhat) {
        if (n == 0 || lines != null) {
            return finish(emptyWhat);
        }
        if (columns[0].length - n > n / 25) {
            for (int c = 0; c < columns.length; c++) {
                columns[c] = Arrays.copyOf(columns[c], n);
            }
        }
        return columns.clone();
    }

    private static boolean increasing(double[] t, int n, boolean equalAllowed) {
        for (int i = 1; i < n; i++) {
            if (!(t[i] > t[i - 1]) && !(equalAllowed && t[i] == t[i - 1])) {
                return false;
            }
        }
        return true;
    }

    /** @return indices 0..n-1 ordered by key, equal keys in their original order (bottom-up merge sort) */
    static int[] stableOrder(double[] key, int n) {
        int[] a = new int[n];
        for (int i = 0; i < n; i++) {
            a[i] = i;
        }
        int[] b = new int[n];
        for (int width = 1; width < n; width *= 2) {
            for (int lo = 0; lo < n; lo += 2 * width) {
                int mid = Math.min(lo + width, n);
                int hi = Math.min(lo + 2 * width, n);
                int i = lo;
                int j = mid;
                int k = lo;
                while (i < mid && j < hi) {
                    // take from the right only when strictly smaller: keeps equal keys in order
                    b[k++] = key[a[j]] < key[a[i]] ? a[j++] : a[i++];
                }
                while (i < mid) {
                    b[k++] = a[i++];
                }
                while (j < hi) {
                    b[k++] = a[j++];
                }
            }
            int[] swap = a;
            a = b;
            b = swap;
        }
        return a;
    }
}
