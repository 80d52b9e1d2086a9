package org.trajeval.core.eval;

import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.MaxGap;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.metric.DriftOptions;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.PairsFrom;
import org.trajeval.core.metric.RpeUnit;

/**
 * Every setting of one evaluation of an estimate against a reference.
 *
 * @param convention the preset these options started from
 * @param association how poses are paired in time
 * @param maxDiffS max timestamp difference for nearest association (s), > 0
 * @param tOffsetS offset added to the estimate's timestamps before association (s)
 * @param overlap what to do with estimate poses outside the reference's span
 * @param alignment transform fitted before ATE
 * @param nToAlign fit the alignment on the first n associated poses; -1 for all
 * @param projection planar projection
 * @param rpeDelta RPE horizon, in {@code rpeUnit}, > 0
 * @param rpeUnit unit of the RPE horizon
 * @param pairSelection consecutive pairs or all pairs
 * @param pairsFrom trajectory the RPE pairs are chosen on
 * @param drift length-normalised drift settings, or {@code null} for no drift
 * @param maxGap longest reference gap the lesson's interpolation bridges (estimate poses inside
 *     longer gaps are dropped and counted)
 * @param timeOffset whether tOffsetS is used as given or estimated from the data
 * @param extraMetrics whether per-axis, heading and speed errors are computed ({@link
 *     org.trajeval.core.metric.ExtraMetrics})
 */
public record EvaluationOptions(Convention convention, AssociationMethod association, double maxDiffS,
        double tOffsetS, OverlapPolicy overlap, AlignmentModel alignment, int nToAlign,
        PlanarProjection projection, double rpeDelta, RpeUnit rpeUnit, PairSelection pairSelection,
        PairsFrom pairsFrom, DriftOptions drift, MaxGap maxGap, TimeOffset timeOffset,
        boolean extraMetrics) {

    /** @throws IllegalArgumentException on a missing or out-of-range setting */
    public EvaluationOptions {
        requireNonNull(convention, "convention");
        requireNonNull(association, "association");
        requireNonNull(overlap, "overlap");
        requireNonNull(alignment, "alignment");
        requireNonNull(projection, "projection");
        requireNonNull(rpeUnit, "rpeUnit");
        requireNonNull(pairSelection, "pairSelection");
        requireNonNull(pairsFrom, "pairsFrom");
        requireNonNull(maxGap, "maxGap");
        requireNonNull(timeOffset, "timeOffset");
        if (!(maxDiffS > 0.0) || !Double.isFinite(maxDiffS)) {
            throw new IllegalArgumentException("max-diff must be a positive number of seconds, got " + maxDiffS);
        }
        if (!Double.isFinite(tOffsetS)) {
            throw new IllegalArgumentException("t-offset must be a finite number of seconds, got " + tOffsetS);
        }
        if (!(rpeDelta > 0.0) || !Double.isFinite(rpeDelta)) {
            throw new IllegalArgumentException("rpe-delta must be positive, got " + rpeDelta);
        }
        if (rpeUnit == RpeUnit.FRAMES && rpeDelta != Math.rint(rpeDelta)) {
            throw new IllegalArgumentException("rpe-delta in frames must be a whole number, got " + rpeDelta);
        }
        if (nToAlign == 0 || nToAlign < -1) {
            throw new IllegalArgumentException("n-to-align must be -1 (all) or positive, got " + nToAlign);
        }
    }

    private static void requireNonNull(Object o, String name) {
        if (o == null) {
            throw new IllegalArgumentException(name + " must be set");
        }
    }

    /**
     * The preset of a convention (see {@link Convention}). The lesson's preset aligns with se2
     * (the lesson is planar); {@link #preset(Convention, boolean)} picks se3 for SE(3) data.
     */
    public static EvaluationOptions preset(Convention convention) {
        return switch (convention) {
            case LESSON -> new EvaluationOptions(convention, AssociationMethod.INTERPOLATE, 0.01, 0.0,
                    OverlapPolicy.CROP, AlignmentModel.SE2, -1, PlanarProjection.NONE, 1.0, RpeUnit.SECONDS,
                    PairSelection.ALL_PAIRS, PairsFrom.ESTIMATE, null, MaxGap.DEFAULT, TimeOffset.GIVEN, false);
            case EVO -> new EvaluationOptions(convention, AssociationMethod.NEAREST, 0.01, 0.0,
                    OverlapPolicy.CROP, AlignmentModel.NONE, -1, PlanarProjection.NONE, 1.0, RpeUnit.FRAMES,
                    PairSelection.CONSECUTIVE, PairsFrom.ESTIMATE, null, MaxGap.DEFAULT, TimeOffset.GIVEN, false);
            case KITTI -> new EvaluationOptions(convention, AssociationMethod.NEAREST, 0.01, 0.0,
                    OverlapPolicy.CROP, AlignmentModel.NONE, -1, PlanarProjection.NONE, 1.0, RpeUnit.FRAMES,
                    PairSelection.CONSECUTIVE, PairsFrom.ESTIMATE, DriftOptions.KITTI, MaxGap.DEFAULT, TimeOffset.GIVEN, false);
        };
    }

    /**
     * The preset of a convention for the given data: for the lesson's convention the rigid
     * alignment is se2 for planar data and se3 for SE(3) data.
     *
     * @param planarData true when both trajectories are planar (or are projected before alignment)
     */
    public static EvaluationOptions preset(Convention convention, boolean planarData) {
        EvaluationOptions o = preset(convention);
        if (convention == Convention.LESSON && !planarData) {
            return o.withAlignment(AlignmentModel.SE3);
        }
        return o;
    }

    /** @return a copy with another association method */
    public EvaluationOptions withAssociation(AssociationMethod v) {
        return new EvaluationOptions(convention, v, maxDiffS, tOffsetS, overlap, alignment, nToAlign, projection,
                rpeDelta, rpeUnit, pairSelection, pairsFrom, drift, maxGap, timeOffset, extraMetrics);
    }

    /** @return a copy with another max difference (s) */
    public EvaluationOptions withMaxDiffS(double v) {
        return new EvaluationOptions(convention, association, v, tOffsetS, overlap, alignment, nToAlign, projection,
                rpeDelta, rpeUnit, pairSelection, pairsFrom, drift, maxGap, timeOffset, extraMetrics);
    }

    /** @return a copy with another time offset (s) */
    public EvaluationOptions withTOffsetS(double v) {
        return new EvaluationOptions(convention, association, maxDiffS, v, overlap, alignment, nToAlign, projection,
                rpeDelta, rpeUnit, pairSelection, pairsFrom, drift, maxGap, timeOffset, extraMetrics);
    }

    /** @return a copy with another overlap policy */
    public EvaluationOptions withOverlap(OverlapPolicy v) {
        return new EvaluationOptions(convention, association, maxDiffS, tOffsetS, v, alignment, nToAlign, projection,
                rpeDelta, rpeUnit, pairSelection, pairsFrom, drift, maxGap, timeOffset, extraMetrics);
    }

    /** @return a copy with another alignment model */
    public EvaluationOptions withAlignment(AlignmentModel v) {
        return new EvaluationOptions(convention, association, maxDiffS, tOffsetS, overlap, v, nToAlign, projection,
                rpeDelta, rpeUnit, pairSelection, pairsFrom, drift, maxGap, timeOffset, extraMetrics);
    }

    /** @return a copy fitting the alignment on the first n poses (-1: all) */
    public EvaluationOptions withNToAlign(int v) {
        return new EvaluationOptions(convention, association, maxDiffS, tOffsetS, overlap, alignment, v, projection,
                rpeDelta, rpeUnit, pairSelection, pairsFrom, drift, maxGap, timeOffset, extraMetrics);
    }

    /** @return a copy with another planar projection */
    public EvaluationOptions withProjection(PlanarProjection v) {
        return new EvaluationOptions(convention, association, maxDiffS, tOffsetS, overlap, alignment, nToAlign, v,
                rpeDelta, rpeUnit, pairSelection, pairsFrom, drift, maxGap, timeOffset, extraMetrics);
    }

    /** @return a copy with another RPE horizon */
    public EvaluationOptions withRpe(double delta, RpeUnit unit) {
        return new EvaluationOptions(convention, association, maxDiffS, tOffsetS, overlap, alignment, nToAlign,
                projection, delta, unit, pairSelection, pairsFrom, drift, maxGap, timeOffset, extraMetrics);
    }

    /** @return a copy with another pair selection */
    public EvaluationOptions withPairSelection(PairSelection v) {
        return new EvaluationOptions(convention, association, maxDiffS, tOffsetS, overlap, alignment, nToAlign,
                projection, rpeDelta, rpeUnit, v, pairsFrom, drift, maxGap, timeOffset, extraMetrics);
    }

    /** @return a copy choosing RPE pairs on another trajectory */
    public EvaluationOptions withPairsFrom(PairsFrom v) {
        return new EvaluationOptions(convention, association, maxDiffS, tOffsetS, overlap, alignment, nToAlign,
                projection, rpeDelta, rpeUnit, pairSelection, v, drift, maxGap, timeOffset, extraMetrics);
    }

    /** @return a copy computing the extra metrics or not */
    public EvaluationOptions withExtraMetrics(boolean v) {
        return new EvaluationOptions(convention, association, maxDiffS, tOffsetS, overlap, alignment, nToAlign,
                projection, rpeDelta, rpeUnit, pairSelection, pairsFrom, drift, maxGap, timeOffset, v);
    }

    /** @return a copy whose offset is given ({@code tOffsetS}) or estimated from the data */
    public EvaluationOptions withTimeOffset(TimeOffset v) {
        return new EvaluationOptions(convention, association, maxDiffS, tOffsetS, overlap, alignment, nToAlign,
                projection, rpeDelta, rpeUnit, pairSelection, pairsFrom, drift, maxGap, v, extraMetrics);
    }

    /** @return a copy with another max gap */
    public EvaluationOptions withMaxGap(MaxGap v) {
        return new EvaluationOptions(convention, association, maxDiffS, tOffsetS, overlap, alignment, nToAlign,
                projection, rpeDelta, rpeUnit, pairSelection, pairsFrom, drift, v, timeOffset, extraMetrics);
    }

    /** @return a copy with other drift settings ({@code null}: no drift) */
    public EvaluationOptions withDrift(DriftOptions v) {
        return new EvaluationOptions(convention, association, maxDiffS, tOffsetS, overlap, alignment, nToAlign,
                projection, rpeDelta, rpeUnit, pairSelection, pairsFrom, v, maxGap, timeOffset, extraMetrics);
    }
}
