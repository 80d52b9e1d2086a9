package org.trajeval.core.eval;

/** The RPE pairs of a {@link PairWalk}, walked again at each reading (pairs that chain, e.g. consecutive). */
final class Walk extends PairRule {
    private final PairWalk walk;

    Walk(AssociatedColumns poses, PairWalk walk) {
        super(poses);
        this.walk = walk;
        PathSpan path = new PathSpan(poses, 0);
        for (walk.start(); walk.next();) {
            int i = walk.i();
            int j = walk.j();
            pairs++;
            sumS += poses.stamp(j) - poses.stamp(i);
            sumM += path.between(i, j);
        }
    }

    @Override
    void errorsInto(double[] trans, double[] rot) {
        AssociatedColumns.Scratch s = new AssociatedColumns.Scratch();
        int p = 0;
        for (walk.start(); walk.next();) {
            poses.rpe(walk.i(), walk.j(), s);
            trans[p] = s.transError;
            rot[p++] = s.rotError;
        }
    }
}
