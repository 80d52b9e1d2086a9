package org.trajeval.core.assoc;

import org.trajeval.core.traj.Trajectory;

/**
 * evo's nearest matching as index pairs (the rule is {@link TimeAssociation}'s): each stamp s of the
 * shorter trajectory, in order, is looked up in the longer one's stamps L (L[k] = t_long(k) + offset,
 * computed where compared, not stored): k = the
 * first index with L[k] &gt; s (numpy's searchsorted, side right), clamped to the last index; the
 * later candidate k wins when L[k] - s &lt;= max diff and is strictly nearer, else the earlier k - 1
 * when s - L[k-1] &lt;= max diff. Stamps never decrease, so k is unique and the search for the next
 * stamp starts at the last k, galloping (probes 1, 2, 4, ... ahead, then bisects: O(log d) for a
 * step of d poses instead of O(log n) per stamp).
 *
 * <p>The stamps are matched in chunks of {@value #CHUNK} that do not depend on one another (each
 * chunk starts its search at 0), so the chunks may run on several threads ({@link IndexTasks}); each
 * chunk writes its pairs at its own start, and the chunks are then moved together in order. The
 * pairs are the same whatever runs the chunks.
 */
final class NearestMatching {
    /** Stamps per chunk. */
    static final int CHUNK = 1 << 16;

    private NearestMatching() {
    }

    /**
     * @param offsetLong added to every stamp of the longer trajectory (s)
     * @param maxDiff largest |dt| of a match (s)
     * @param idxShort receives the shorter trajectory's index of pair p at p (length &gt;= its size)
     * @param idxLong receives the longer trajectory's index of pair p at p (same length)
     * @return the number of pairs
     */
    static int match(Trajectory shortTraj, Trajectory longTraj, double offsetLong, double maxDiff, int[] idxShort,
            int[] idxLong, IndexTasks tasks) {
        int ns = shortTraj.size();
        int[] found = new int[chunks(ns)];
        tasks.forEach(found.length, c -> found[c] = matchChunk(shortTraj, longTraj, offsetLong, maxDiff, c * CHUNK,
                end(c, ns), idxShort, idxLong));
        int count = 0;
        for (int c = 0; c < found.length; c++) {
            int from = c * CHUNK;
            if (count != from) {
                System.arraycopy(idxShort, from, idxShort, count, found[c]);
                System.arraycopy(idxLong, from, idxLong, count, found[c]);
            }
            count += found[c];
        }
        return count;
    }

    private static int chunks(int n) {
        return (int) (((long) n + CHUNK - 1) / CHUNK);
    }

    private static int end(int c, int n) {
        return (int) Math.min((long) (c + 1) * CHUNK, n);
    }

    /** Matches short stamps [from, to) and writes their pairs from index {@code from} on; @return how many */
    private static int matchChunk(Trajectory shortTraj, Trajectory longTraj, double offsetLong, double maxDiff,
            int from, int to, int[] idxShort, int[] idxLong) {
        int nl = longTraj.size();
        double first = longTraj.t(0) + offsetLong;
        double last = longTraj.t(nl - 1) + offsetLong;
        int count = from;
        int hint = 0;
        for (int i = from; i < to; i++) {
            double s = shortTraj.t(i);
            if (s < first - maxDiff || s > last + maxDiff) {
                continue;
            }
            int k = upperBound(longTraj, offsetLong, s, hint);
            hint = k;
            if (k >= nl) {
                k = nl - 1;
            }
            double diffUb = (longTraj.t(k) + offsetLong) - s;
            double diffLb = k > 0 ? s - (longTraj.t(k - 1) + offsetLong) : Double.POSITIVE_INFINITY;
            int best;
            if (diffUb <= maxDiff && diffUb < diffLb) {
                best = k;
            } else if (diffLb <= maxDiff && diffLb <= diffUb) {
                best = k - 1;
            } else {
                continue;
            }
            idxShort[count] = i;
            idxLong[count++] = best;
        }
        return count - from;
    }

    /**
     * @return the first index k &gt;= from with L[k] = t(k) + offset &gt; v (s), or t's size, for
     *     L[k] &lt;= v at every k &lt; from: gallops from {@code from}, then bisects
     */
    static int upperBound(Trajectory t, double offset, double v, int from) {
        int n = t.size();
        int lo = from; // L[k] <= v for every k < lo
        int probe = from;
        long step = 1;
        while (probe < n && !(t.t(probe) + offset > v)) {
            lo = probe + 1;
            probe = (int) Math.min(n, lo + step);
            step <<= 1;
        }
        int hi = probe; // L[hi] > v, or hi = n
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (t.t(mid) + offset > v) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        return lo;
    }
}
