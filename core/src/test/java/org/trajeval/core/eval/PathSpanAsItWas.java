package org.trajeval.core.eval;

/**
 * {@link PathSpan} as it was before each hop was computed once (verbatim, test sources only): two
 * running sums of hops from a start pose, to i and to j, each adding its own hops. The reference
 * for {@link PathSpanTest}.
 */
final class PathSpanAsItWas {
    private final AssociatedColumns poses;
    private int pathI;
    private int pathJ;
    private double toI; // path length from the start pose to i (m)
    private double toJ; // ... to j

    PathSpanAsItWas(AssociatedColumns poses, int start) {
        this.poses = poses;
        pathI = start;
        pathJ = start;
    }

    /** @return the reference path length from pose i to pose j (m) */
    double between(int i, int j) {
        while (pathI < i) {
            toI += poses.hop(pathI++);
        }
        if (pathJ < pathI) {
            pathJ = pathI;
            toJ = toI;
        }
        while (pathJ < j) {
            toJ += poses.hop(pathJ++);
        }
        return toJ - toI;
    }
}
