package org.trajeval.core.eval;

import org.trajeval.core.assoc.AssociationOptions;
import org.trajeval.core.assoc.InterpolatedReference;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.assoc.ReferenceSampling;
import org.trajeval.core.assoc.TimeAssociation;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/**
 * The association of {@link ColumnarEvaluator} and what the report says of it: the associated poses
 * as columns, the estimate and reference poses dropped, the largest reference gap (s), the largest
 * reference acceleration (m/s^2) and the gap limit (s) that applied.
 */
record ColumnarAssociation(AssociatedColumns pairs, int dropped, int droppedReference, double maxGapS,
        double aMaxMps2, double gapLimitS) {

    /** The lesson's association: the reference interpolated at the estimate stamps inside its span. */
    static ColumnarAssociation interpolate(Trajectory ref, Trajectory est, EvaluationOptions o, boolean planar,
            Parallelism par) {
        int nr = ref.size();
        int ne = est.size();
        if (nr < 2) {
            return null;
        }
        double off = o.tOffsetS();
        double t0 = ref.t(0);
        double tn = ref.t(nr - 1);
        int k0 = 0;
        while (k0 < ne && est.t(k0) + off < t0) {
            k0++;
        }
        int k1 = ne;
        while (k1 > k0 && est.t(k1 - 1) + off > tn) {
            k1--;
        }
        int m = k1 - k0;
        if (m < 2 || (o.overlap() == OverlapPolicy.STRICT && m != ne)) {
            return null;
        }
        int spanLo = 0;
        while (spanLo + 1 < nr && ref.t(spanLo + 1) <= est.t(k0) + off) {
            spanLo++;
        }
        int spanHi = nr - 1;
        while (spanHi - 1 > spanLo && ref.t(spanHi - 1) >= est.t(k1 - 1) + off) {
            spanHi--;
        }
        // the reference's sampling (one thread) beside the allocation of the interpolated columns and
        // the pairs' cache (zeroed, i.e. page faults: 28 B per pose for SE(3) data)
        int lo = spanLo;
        int hi = spanHi;
        int first = k0;
        double[][] sampling = new double[1][];
        InterpolatedReference[] interp = new InterpolatedReference[1];
        AssociatedColumns[] pairs = new AssociatedColumns[1];
        par.all(() -> sampling[0] = referenceSampling(ref, lo, hi, Parallelism.SEQUENTIAL), () -> {
            interp[0] = planar ? InterpolatedReference.planar((PlanarTrajectory) ref, m)
                    : InterpolatedReference.spatial((SpatialTrajectory) ref, m);
            pairs[0] = AssociatedColumns.interpolated(ref, est, interp[0], first, m, off);
        });
        double limit = o.maxGap().limitS(ref);
        if (sampling[0][0] > limit) {
            return null; // a reference gap longer than the limit: the general path drops and counts
        }
        par.forEachChunk(m, (c, from, to) -> interp[0].fill(k -> est.t(first + k) + off, from, to));
        return new ColumnarAssociation(pairs[0], ne - m, 0, sampling[0][0], sampling[0][1], limit);
    }

    /** evo's nearest matching, as index maps; the search, the counts and the sampling spread over {@code par}. */
    static ColumnarAssociation nearest(Trajectory ref, Trajectory est, EvaluationOptions o, String refName,
            String estName, Parallelism par) {
        TimeAssociation.NearestPairs np = TimeAssociation.nearestPairs(ref, est, new AssociationOptions(
                o.association(), o.maxDiffS(), o.tOffsetS(), o.overlap(), o.maxGap()), refName, estName, par);
        int m = np.count();
        if (m < 2) {
            return null;
        }
        int first = np.reference()[0];
        int last = np.reference()[m - 1];
        int[] distinct = new int[2];
        par.all(() -> distinct[0] = np.distinctEstimate(), () -> distinct[1] = np.distinctReference());
        double[] sampling = referenceSampling(ref, first, last, par);
        return new ColumnarAssociation(
                AssociatedColumns.matched(ref, est, np.reference(), np.estimate(), m, o.tOffsetS(), par),
                est.size() - distinct[0], ref.size() - distinct[1], sampling[0], sampling[1],
                Double.POSITIVE_INFINITY);
    }

    /** @return {max gap (s), max acceleration (m/s^2)} of the reference over poses [lo, hi], chunk by chunk */
    private static double[] referenceSampling(Trajectory ref, int lo, int hi, Parallelism par) {
        int n = hi - lo + 1;
        double[] gap = new double[Parallelism.chunks(n)];
        double[] acc = new double[gap.length];
        par.forEachChunk(n, (c, from, to) -> {
            gap[c] = ReferenceSampling.maxGap(ref, lo + from, Math.min(lo + to, hi));
            acc[c] = ReferenceSampling.maxAcceleration(ref, lo + from, lo + to - 1);
        });
        double h = 0.0;
        double a = 0.0;
        for (int c = 0; c < gap.length; c++) {
            h = Math.max(h, gap[c]);
            a = Math.max(a, acc[c]);
        }
        return new double[] {h, a};
    }
}
