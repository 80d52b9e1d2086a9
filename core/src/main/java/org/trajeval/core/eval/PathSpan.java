package org.trajeval.core.eval;

/**
 * Reference path lengths between the poses of pairs met in order (i and j never decrease):
 * two running sums of {@link AssociatedColumns#hop}s from a start pose, to i and to j.
 */
final class PathSpan {
    private final AssociatedColumns poses;
    private int pathI;
    private int pathJ;
    private double toI; // path length from the start pose to i (m)
    private double toJ; // ... to j

    PathSpan(AssociatedColumns poses, int start) {
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
