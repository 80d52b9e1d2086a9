package org.trajeval.core.eval;

/**
 * Reference path lengths between the poses of pairs met in order (i and j never decrease, i &lt;= j):
 * the running sum s_k = hop(start) + ... + hop(k - 1) of {@link AssociatedColumns#hop}s from a start
 * pose (m), and between(i, j) = s_j - s_i. Each hop is computed once, as the sum reaches pose k; the
 * last {@value #RING} sums wait in a ring for the start poses that reach them (16 KiB). A start pose
 * that lags further behind (pairs more than {@value #RING} poses long) carries its own running sum,
 * hop by hop. Both sums add the same hops in the same order from 0, so s_i is the same double
 * whichever gives it.
 */
final class PathSpan {
    /** Sums kept (a power of two). */
    static final int RING = 2048;
    private static final int MASK = RING - 1;

    private final AssociatedColumns poses;
    private final double[] sums = new double[RING]; // s_k at k & MASK for k in (reached - RING, reached]
    private int reached; // the last pose with its sum in the ring
    private double toReached; // s_reached (m)
    private int pathI;
    private double toI; // s_pathI (m)

    PathSpan(AssociatedColumns poses, int start) {
        this.poses = poses;
        reached = start;
        pathI = start;
        // sums[start & MASK] = 0.0 already
    }

    /** @return the reference path length from pose i to pose j (m) */
    double between(int i, int j) {
        int k = reached;
        double to = toReached;
        while (k < j) {
            to += poses.hop(k++);
            sums[k & MASK] = to;
        }
        reached = k;
        toReached = to;
        if (k - i < RING) {
            toI = sums[i & MASK];
            pathI = i;
        } else {
            while (pathI < i) {
                toI += poses.hop(pathI++);
            }
        }
        return to - toI;
    }
}
