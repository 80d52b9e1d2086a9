package org.trajeval.core.eval;

import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.RpeUnit;

/** Index pairs on the associated poses, by the rules of the general path ({@code PairIndices}). */
final class PairWalk {
    private final AssociatedColumns poses;
    private final int m;
    private final double delta;
    private final RpeUnit unit;
    private final boolean all;
    private int i;
    private int j;
    private boolean first;

    PairWalk(AssociatedColumns poses, double delta, RpeUnit unit, PairSelection sel) {
        this.poses = poses;
        this.m = poses.size();
        this.delta = delta;
        this.unit = unit;
        this.all = sel == PairSelection.ALL_PAIRS;
    }

    void start() {
        i = 0;
        j = 0;
        first = true;
    }

    int i() {
        return i;
    }

    int j() {
        return j;
    }

    /** Advances to the next pair; false when there is none. */
    boolean next() {
        if (unit == RpeUnit.FRAMES) {
            int d = (int) delta;
            if (first) {
                first = false;
                i = 0;
            } else {
                i += all ? 1 : d;
            }
            j = i + d;
            return j < m;
        }
        if (first) {
            first = false;
            i = 0;
        } else if (all) {
            i++;
        } else {
            if (j == i) {
                return false;
            }
            i = j;
        }
        if (i >= m) {
            return false;
        }
        double target = poses.stamp(i) + delta;
        if (j < i) {
            j = i;
        }
        while (j < m && poses.stamp(j) < target) {
            j++;
        }
        return j < m && j != i;
    }
}
