package org.trajeval.core.assoc;

import org.trajeval.core.traj.PoseSequence;

/**
 * Reference and estimate poses paired one-to-one by index after time association.
 *
 * @param reference reference pose k (interpolated or nearest)
 * @param estimate estimate pose k
 * @param timestamps time of pair k on the estimate's clock, offset applied (s)
 * @param droppedEstimate estimate poses without a partner (outside the overlap or beyond max diff)
 * @param droppedReference reference poses never used (nearest association; 0 for interpolation)
 * @param maxGapS largest reference sampling gap h inside the matched span (s)
 * @param aMaxMps2 largest reference acceleration norm inside the matched span (m/s^2)
 * @param gapLimitS longest reference gap interpolation bridged (s); +inf for nearest association
 * @param gaps reference gaps longer than the limit with estimate poses dropped in them (counted in
 *     {@code droppedEstimate}), in time order
 */
public record AssociatedPoses(PoseSequence reference, PoseSequence estimate, double[] timestamps,
        int droppedEstimate, int droppedReference, double maxGapS, double aMaxMps2, double gapLimitS,
        java.util.List<ReferenceGap> gaps) {

    /** @throws NullPointerException without gaps */
    public AssociatedPoses {
        gaps = java.util.List.copyOf(gaps);
    }

    /** @return estimate poses dropped inside reference gaps longer than the limit */
    public int droppedInGaps() {
        int n = 0;
        for (ReferenceGap g : gaps) {
            n += g.dropped();
        }
        return n;
    }

    /** @return number of associated pairs */
    public int size() {
        return estimate.size();
    }

    /**
     * The lesson's Proposition 2: linear interpolation of a reference whose acceleration norm
     * is at most A_max, sampled with gaps at most h, errs by at most A_max h^2 / 8 (m).
     *
     * @return A_max h^2 / 8 (m)
     */
    public double interpolationErrorBoundM() {
        return aMaxMps2 * maxGapS * maxGapS / 8.0;
    }
}
