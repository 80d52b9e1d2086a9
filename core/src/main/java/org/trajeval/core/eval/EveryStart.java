package org.trajeval.core.eval;

import org.trajeval.core.metric.RpeUnit;

/**
 * RPE from every start pose i = 0, 1, ...: pair p starts at pose p, so chunks of start
 * poses are independent. The pairs end at the first start pose without a partner.
 */
final class EveryStart extends PairRule {
    private final double delta;
    private final boolean frames;
    private final Parallelism par;
    private final int m;

    EveryStart(AssociatedColumns poses, double delta, RpeUnit unit, Parallelism par) {
        super(poses);
        this.delta = delta;
        this.frames = unit == RpeUnit.FRAMES;
        this.par = par;
        this.m = poses.size();
        int chunks = Parallelism.chunks(m);
        int[] firstWithout = new int[chunks];
        double[] chunkS = new double[chunks];
        double[] chunkM = new double[chunks];
        par.forEachChunk(m, (c, from, to) -> {
            double s = 0;
            double len = 0;
            PathSpan path = new PathSpan(poses, from);
            int j = frames ? from : firstPartner(from);
            int i = from;
            for (; i < to; i++) {
                j = partner(i, j);
                if (j >= m || j == i && !frames) {
                    break;
                }
                s += poses.stamp(j) - poses.stamp(i);
                len += path.between(i, j);
            }
            firstWithout[c] = i;
            chunkS[c] = s;
            chunkM[c] = len;
        });
        pairs = m;
        for (int c = 0; c < chunks; c++) {
            sumS += chunkS[c];
            sumM += chunkM[c];
            if (firstWithout[c] < Math.min((long) (c + 1) * Parallelism.CHUNK, m)) {
                pairs = firstWithout[c];
                break;
            }
        }
    }

    /** @return the partner of start pose i, given the partner j of an earlier start in the same chunk */
    private int partner(int i, int j) {
        if (frames) {
            long k = (long) i + (int) delta;
            return k >= m ? m : (int) k;
        }
        double target = poses.stamp(i) + delta;
        j = Math.max(i, j);
        while (j < m && poses.stamp(j) < target) {
            j++;
        }
        return j;
    }

    /** @return the first pose j &gt;= i with t_j &gt;= t_i + delta (s), or m (binary search) */
    private int firstPartner(int i) {
        double target = poses.stamp(i) + delta;
        int lo = i;
        int hi = m;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (poses.stamp(mid) < target) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    @Override
    void errorsInto(double[] trans, double[] rot) {
        par.forEachChunk(pairs, (c, from, to) -> {
            AssociatedColumns.Scratch s = new AssociatedColumns.Scratch();
            s.posesInRuns = true;
            int j = frames ? from : firstPartner(from);
            for (int i = from; i < to; i++) {
                j = partner(i, j);
                poses.rpe(i, j, s);
                trans[i] = s.transError;
                rot[i] = s.rotError;
            }
        });
    }
}
