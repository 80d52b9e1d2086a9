package org.trajeval.core.eval;

/**
 * RPE in frames between poses d apart, not overlapping: pair p is (p d, p d + d), so chunks
 * of pairs are independent (evo's default, {@code --delta 1 --delta_unit f}).
 */
final class Stride extends PairRule {
    private final int d;
    private final Parallelism par;

    Stride(AssociatedColumns poses, int d, Parallelism par) {
        super(poses);
        this.d = d;
        this.par = par;
        int m = poses.size();
        pairs = m > d ? (m - 1) / d : 0; // the p with p d + d < m
        int chunks = Parallelism.chunks(pairs);
        double[] chunkS = new double[chunks];
        double[] chunkM = new double[chunks];
        par.forEachChunk(pairs, (c, from, to) -> {
            double sum = 0;
            double len = 0;
            PathSpan path = new PathSpan(poses, from * d);
            for (int p = from; p < to; p++) {
                int i = p * d;
                sum += poses.stamp(i + d) - poses.stamp(i);
                len += path.between(i, i + d);
            }
            chunkS[c] = sum;
            chunkM[c] = len;
        });
        for (int c = 0; c < chunks; c++) {
            sumS += chunkS[c];
            sumM += chunkM[c];
        }
    }

    @Override
    void errorsInto(double[] trans, double[] rot) {
        par.forEachChunk(pairs, (c, from, to) -> {
            AssociatedColumns.Scratch s = new AssociatedColumns.Scratch();
            s.posesInRuns = d == 1;
            for (int p = from; p < to; p++) {
                poses.rpe(p * d, p * d + d, s);
                trans[p] = s.transError;
                rot[p] = s.rotError;
            }
        });
    }
}
