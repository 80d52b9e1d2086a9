package org.trajeval.core.assoc;

/**
 * Settings of the time association.
 *
 * @param method how poses are paired
 * @param maxDiffS max timestamp difference for nearest matching (s)
 * @param tOffsetS offset added to the estimate's timestamps (s)
 * @param overlap what to do with estimate poses outside the reference's span (interpolation)
 * @param maxGap longest reference gap the lesson's interpolation bridges
 */
public record AssociationOptions(AssociationMethod method, double maxDiffS, double tOffsetS, OverlapPolicy overlap,
        MaxGap maxGap) {
    /** Settings with the default max gap. */
    public AssociationOptions(AssociationMethod method, double maxDiffS, double tOffsetS, OverlapPolicy overlap) {
        this(method, maxDiffS, tOffsetS, overlap, MaxGap.DEFAULT);
    }
}
