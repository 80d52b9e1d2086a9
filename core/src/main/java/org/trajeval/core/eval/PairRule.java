package org.trajeval.core.eval;

import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.RpeUnit;

/**
 * The RPE pairs of one pair-selection rule ({@link EveryStart}, {@link Stride}, {@link Walk}), with the
 * sums behind the mean horizon.
 */
abstract class PairRule {
    final AssociatedColumns poses;
    /** Number of pairs. */
    int pairs;
    /** Sum over pairs of t_j - t_i (s). */
    double sumS;
    /** Sum over pairs of the reference path length from i to j (m). */
    double sumM;

    PairRule(AssociatedColumns poses) {
        this.poses = poses;
    }

    /** @return the rule of these options: every start pose, a stride in frames, or the general walk */
    static PairRule of(AssociatedColumns pairs, EvaluationOptions o, Parallelism par) {
        return o.pairSelection() == PairSelection.ALL_PAIRS && o.rpeDelta() > 0
                ? new EveryStart(pairs, o.rpeDelta(), o.rpeUnit(), par)
                : o.rpeUnit() == RpeUnit.FRAMES && o.rpeDelta() >= 1 ? new Stride(pairs, (int) o.rpeDelta(), par)
                : new Walk(pairs, new PairWalk(pairs, o.rpeDelta(), o.rpeUnit(), o.pairSelection()));
    }

    final int pairs() {
        return pairs;
    }

    final double sumS() {
        return sumS;
    }

    final double sumM() {
        return sumM;
    }

    /** Writes the translation error (m) and rotation error (rad) of pair p to trans[p] and rot[p]. */
    abstract void errorsInto(double[] trans, double[] rot);
}
