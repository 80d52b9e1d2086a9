package org.trajeval.core.assoc;

import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.PoseSequence;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/**
 * Pairs estimate poses with reference poses in time (see {@link AssociationMethod}).
 *
 * <p>Nearest matching follows evo exactly: the shorter trajectory's stamps are looked up in the
 * longer one's (the offset is added to the estimate: to the longer stamps when the estimate is
 * longer, subtracted from the reference's otherwise); a match needs |dt| <= max diff; ties go
 * to the earlier stamp. Example: reference stamps 0.00, 0.02 s, estimate stamp 0.01 s, max
 * diff 0.01 s: both differ by 0.01 s, the earlier (0.00 s) wins.
 */
public final class TimeAssociation {
    private TimeAssociation() {
    }

    /**
     * @param referenceName file name used in error messages
     * @param estimateName file name used in error messages
     * @throws InputException NO_OVERLAP when nothing can be paired, OUTSIDE_OVERLAP for the strict
     *     policy when an estimate pose lies outside the reference's span
     */
    public static AssociatedPoses compute(Trajectory reference, Trajectory estimate, AssociationOptions options,
            String referenceName, String estimateName) {
        return switch (options.method()) {
            case INTERPOLATE -> interpolateAtEstimate(reference, estimate, options, referenceName, estimateName);
            case NEAREST, NEAREST_INTERPOLATED -> nearest(reference, estimate, options, referenceName, estimateName);
        };
    }

    // ---------------------------------------------------------------- the lesson's interpolation

    private static AssociatedPoses interpolateAtEstimate(Trajectory ref, Trajectory est, AssociationOptions o,
            String refName, String estName) {
        if (ref.size() < 2) {
            throw new InputException(refName, 0, null, InputProblem.TOO_FEW_POSES,
                    "interpolation needs at least 2 reference poses, the file has " + ref.size(), null);
        }
        double off = o.tOffsetS();
        double t0 = ref.t(0);
        double tn = ref.t(ref.size() - 1);
        int n = est.size();
        int[] keep = new int[n];
        double[] tq = new double[n];
        int count = 0;
        double limit = o.maxGap().limitS(ref);
        java.util.List<ReferenceGap> gaps = new java.util.ArrayList<>();
        int seg = 1;
        int last = ref.size() - 1;
        int gapSeg = -1;
        int inGap = 0;
        for (int i = 0; i < n; i++) {
            double t = est.t(i) + off;
            if (t >= t0 && t <= tn) {
                // bracketing reference poses seg - 1, seg: first seg with t(seg) >= t (stamps increase)
                while (seg < last && ref.t(seg) < t) {
                    seg++;
                }
                if (t > ref.t(seg - 1) && t < ref.t(seg) && ref.t(seg) - ref.t(seg - 1) > limit) {
                    if (seg != gapSeg) {
                        if (inGap > 0) {
                            gaps.add(new ReferenceGap(ref.t(gapSeg - 1), ref.t(gapSeg), inGap));
                        }
                        gapSeg = seg;
                        inGap = 0;
                    }
                    inGap++;
                    continue;
                }
                keep[count] = i;
                tq[count++] = t;
            } else if (o.overlap() == OverlapPolicy.STRICT) {
                throw new InputException(estName, 0, "t", InputProblem.OUTSIDE_OVERLAP,
                        String.format("estimate pose %d at %.6f s (offset applied) lies outside the reference's "
                                + "time span [%.6f, %.6f] s; the overlap policy is strict (use --overlap crop to "
                                + "drop such poses)", i, t, t0, tn), null);
            }
        }
        if (inGap > 0) {
            gaps.add(new ReferenceGap(ref.t(gapSeg - 1), ref.t(gapSeg), inGap));
        }
        if (count == 0) {
            throw noOverlap(ref, est, o, refName, estName);
        }
        double[] stamps = java.util.Arrays.copyOf(tq, count);
        PoseSequence refPoses;
        if (ref instanceof PlanarTrajectory planar && est instanceof PlanarTrajectory) {
            refPoses = InterpolatedReference.planarAt(planar, stamps);
        } else {
            refPoses = InterpolatedReference.spatialAt(ref.toSpatial(), stamps);
        }
        PoseSequence estPoses = est.toSpatial().poses().select(keep, count);
        int[] span = span(ref, stamps[0], stamps[count - 1]);
        return new AssociatedPoses(refPoses, estPoses, stamps, n - count, 0,
                ReferenceSampling.maxGapUpTo(ref, span[0], span[1], limit),
                ReferenceSampling.maxAcceleration(ref, span[0], span[1]), limit, gaps);
    }

    // ---------------------------------------------------------------- evo's nearest matching

    /**
     * Pairs by evo's nearest matching (see the class comment), as indices.
     *
     * @param referenceName file name used in error messages
     * @param estimateName file name used in error messages
     * @return the matched index pairs, in increasing order of both indices
     * @throws InputException NO_OVERLAP when nothing can be paired
     */
    public static NearestPairs nearestPairs(Trajectory ref, Trajectory est, AssociationOptions o,
            String referenceName, String estimateName) {
        return nearestPairs(ref, est, o, referenceName, estimateName, IndexTasks.SERIAL);
    }

    /**
     * As {@link #nearestPairs(Trajectory, Trajectory, AssociationOptions, String, String)}, with
     * the independent chunks of the search handed to {@code tasks} (which may run them on several
     * threads): the same pairs.
     *
     * @param tasks runs the chunks of the search
     */
    public static NearestPairs nearestPairs(Trajectory ref, Trajectory est, AssociationOptions o,
            String referenceName, String estimateName, IndexTasks tasks) {
        boolean estLonger = est.size() > ref.size();
        Trajectory shortTraj = estLonger ? ref : est;
        Trajectory longTraj = estLonger ? est : ref;
        double offsetLong = estLonger ? o.tOffsetS() : -o.tOffsetS();
        int ns = shortTraj.size();
        int[] idxShort = new int[ns];
        int[] idxLong = new int[ns];
        int count = NearestMatching.match(shortTraj, longTraj, offsetLong, o.maxDiffS(), idxShort, idxLong, tasks);
        if (count == 0) {
            throw noOverlap(ref, est, o, referenceName, estimateName);
        }
        return new NearestPairs(estLonger ? idxShort : idxLong, estLonger ? idxLong : idxShort, count);
    }

    /**
     * Index pairs of nearest matching: pair k is reference pose {@code reference[k]} and estimate
     * pose {@code estimate[k]}, for k &lt; count (the arrays may be longer).
     */
    public record NearestPairs(int[] reference, int[] estimate, int count) {
        /** @return the number of distinct reference poses used */
        public int distinctReference() {
            return countDistinct(reference, count);
        }

        /** @return the number of distinct estimate poses used */
        public int distinctEstimate() {
            return countDistinct(estimate, count);
        }
    }

    private static AssociatedPoses nearest(Trajectory ref, Trajectory est, AssociationOptions o,
            String refName, String estName) {
        NearestPairs np = nearestPairs(ref, est, o, refName, estName);
        boolean estLonger = est.size() > ref.size();
        Trajectory shortTraj = estLonger ? ref : est;
        int count = np.count();
        int[] idxShort = estLonger ? np.reference() : np.estimate();
        int[] idxRef = np.reference();
        int[] idxEst = np.estimate();
        SpatialTrajectory refS = ref.toSpatial();
        SpatialTrajectory estS = est.toSpatial();
        PoseSequence refPoses;
        PoseSequence estPoses;
        double[] stamps = new double[count];
        if (o.method() == AssociationMethod.NEAREST_INTERPOLATED) {
            // the longer trajectory is interpolated at the matched stamps of the shorter one,
            // converted back to the longer one's own clock
            double[] tq = new double[count];
            for (int k = 0; k < count; k++) {
                tq[k] = shortTraj.t(idxShort[k]) + (estLonger ? -o.tOffsetS() : o.tOffsetS());
            }
            PoseSequence shortPoses = (estLonger ? refS : estS).poses().select(idxShort, count);
            PoseSequence longPoses = InterpolatedReference.spatialAt(estLonger ? estS : refS, tq);
            refPoses = estLonger ? shortPoses : longPoses;
            estPoses = estLonger ? longPoses : shortPoses;
            for (int k = 0; k < count; k++) {
                stamps[k] = estLonger ? tq[k] + o.tOffsetS() : est.t(idxShort[k]) + o.tOffsetS();
            }
        } else {
            refPoses = refS.poses().select(idxRef, count);
            estPoses = estS.poses().select(idxEst, count);
            for (int k = 0; k < count; k++) {
                stamps[k] = est.t(idxEst[k]) + o.tOffsetS();
            }
        }
        int distinctEst = np.distinctEstimate();
        int distinctRef = np.distinctReference();
        int first = idxRef[0];
        int last = idxRef[count - 1];
        return new AssociatedPoses(refPoses, estPoses, stamps, est.size() - distinctEst, ref.size() - distinctRef,
                ReferenceSampling.maxGap(ref, first, last), ReferenceSampling.maxAcceleration(ref, first, last),
                Double.POSITIVE_INFINITY, java.util.List.of());
    }

    private static int countDistinct(int[] sortedIndices, int count) {
        int distinct = 0;
        for (int k = 0; k < count; k++) {
            if (k == 0 || sortedIndices[k] != sortedIndices[k - 1]) {
                distinct++;
            }
        }
        return distinct;
    }

    /** Indices of the reference poses bracketing [tFirst, tLast]. */
    private static int[] span(Trajectory ref, double tFirst, double tLast) {
        int n = ref.size();
        int lo = 0;
        while (lo + 1 < n && ref.t(lo + 1) <= tFirst) {
            lo++;
        }
        int hi = n - 1;
        while (hi - 1 > lo && ref.t(hi - 1) >= tLast) {
            hi--;
        }
        return new int[] {lo, hi};
    }

    private static InputException noOverlap(Trajectory ref, Trajectory est, AssociationOptions o,
            String refName, String estName) {
        String detail = String.format("no pose of %s could be paired with %s: the estimate spans [%.6f, %.6f] s "
                + "(offset %.6f s applied), the reference [%.6f, %.6f] s", estName, refName,
                est.t(0) + o.tOffsetS(), est.t(est.size() - 1) + o.tOffsetS(), o.tOffsetS(), ref.t(0),
                ref.t(ref.size() - 1));
        if (o.method() != AssociationMethod.INTERPOLATE) {
            detail += String.format(" and no stamps lie within the max difference %.6f s (--max-diff)", o.maxDiffS());
        }
        detail += "; check the time unit (--time-unit) or pass --t-offset";
        return new InputException(estName, 0, "t", InputProblem.NO_OVERLAP, detail, null);
    }
}
