package org.trajeval.core.eval;

import java.util.List;
import org.trajeval.core.align.Alignment;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.AssociationOptions;
import org.trajeval.core.assoc.InterpolatedReference;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.assoc.ReferenceSampling;
import org.trajeval.core.assoc.TimeAssociation;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.metric.Coverage;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.stats.ErrorStatistics;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/**
 * The evaluator of {@link Evaluator#evaluate}: planar and SE(3) pairs, interpolated or nearest
 * association, every alignment model, RPE in seconds or frames, on primitive columns without
 * per-pose objects ({@link AssociatedColumns}) and in fixed chunks spread over the threads. The
 * numbers are the general path's ({@link Evaluator#run}, which also keeps the per-pose data), bit
 * for bit for the per-pose errors. Planar pairs aligned about +z (every model but se3/sim3 fits
 * that are not) take 2x2 blocks of (cos, sin) of the yaws instead of 3x3 matrices ({@link PlanarErrors}).
 *
 * <p>Memory on top of the inputs: the reference interpolated at the estimate stamps (planar 24 B;
 * SE(3) 20 B per pose: its bracket and the ATE rotation errors the RPE computes; none for nearest
 * matching, 8 B of index maps instead) and two error arrays (16 B per pose) that the RPE and then
 * the ATE fill; every RPE pair and every ATE pose is computed once.
 */
final class ColumnarEvaluator {
    private ColumnarEvaluator() {
    }

    /** @return true when this evaluator computes these options for this pair exactly as the general path */
    static boolean applies(LoadedTrajectory ref, LoadedTrajectory est, EvaluationOptions o) {
        boolean projection = o.projection() == PlanarProjection.NONE
                || o.projection() == PlanarProjection.XY_BEFORE_ALIGNMENT;
        boolean association = o.association() == AssociationMethod.INTERPOLATE
                || o.association() == AssociationMethod.NEAREST;
        return projection && association
                && !o.extraMetrics() && (o.rpeUnit() == RpeUnit.SECONDS || o.rpeUnit() == RpeUnit.FRAMES)
                && o.drift() == null;
    }

    /** @return the report's parts, or {@code null} when the general path must decide (refusals, edge cases) */
    static ReportParts evaluate(Trajectory reference, Trajectory estimate, EvaluationOptions o, String refName,
            String estName, Parallelism par) {
        Trajectory ref = reference;
        Trajectory est = estimate;
        if (o.projection() == PlanarProjection.XY_BEFORE_ALIGNMENT) {
            ref = ref.toPlanar();
            est = est.toPlanar();
        }
        boolean planar = ref instanceof PlanarTrajectory && est instanceof PlanarTrajectory;
        if (!planar) {
            ref = ref.toSpatial();
            est = est.toSpatial();
        }
        Associated a = o.association() == AssociationMethod.INTERPOLATE ? interpolate(ref, est, o, planar, par)
                : nearest(ref, est, o, refName, estName);
        if (a == null) {
            return null;
        }
        AssociatedColumns pairs = a.pairs();
        int m = pairs.size();
        AlignmentTransform tf = Alignment.fit(o.alignment(), pairs, o.nToAlign(), estName);
        List<EvaluationReport.Warning> warnings = AlignmentCheck.check(tf, pairs.reference(), pairs.estimate(), m,
                planar);
        pairs.align(tf);

        // ---- errors and statistics: each RPE pair and each ATE pose computed once, translation
        // into one array and rotation into another; the ATE reuses the arrays of the RPE
        PairRule rule = o.pairSelection() == PairSelection.ALL_PAIRS && o.rpeDelta() > 0
                ? new EveryStart(pairs, o.rpeDelta(), o.rpeUnit(), par)
                : o.rpeUnit() == RpeUnit.FRAMES && o.rpeDelta() >= 1 ? new Stride(pairs, (int) o.rpeDelta(), par)
                : new Walk(pairs, new PairWalk(pairs, o.rpeDelta(), o.rpeUnit(), o.pairSelection()));
        double[] trans = new double[m];
        double[] rot = new double[m];
        rule.errorsInto(trans, rot);
        int count = rule.pairs();
        ErrorStatistics rpeTrans = ErrorStatistics.ofInPlace(trans, count);
        ErrorStatistics rpeRot = ErrorStatistics.ofInPlace(rot, count);
        par.forEachChunk(m, (c, from, to) -> {
            pairs.ateInto(from, to, trans, rot, new AssociatedColumns.Scratch());
        });
        ErrorStatistics ateTrans = ErrorStatistics.ofInPlace(trans, m);
        ErrorStatistics ateRot = ErrorStatistics.ofInPlace(rot, m);
        Coverage coverage = Coverage.compute(pairs::stamp, m, ref.t(0), ref.t(ref.size() - 1));
        return new ReportParts(m, a.dropped(), a.droppedReference(), a.maxGapS(), a.aMaxMps2(), a.gapLimitS(), tf,
                warnings, ateTrans, ateRot, rpeTrans, rpeRot, count,
                count == 0 ? Double.NaN : rule.sumS() / count, count == 0 ? Double.NaN : rule.sumM() / count,
                coverage);
    }

    /** The association and what the report says of it. */
    private record Associated(AssociatedColumns pairs, int dropped, int droppedReference, double maxGapS,
            double aMaxMps2, double gapLimitS) {
    }

    /** The lesson's association: the reference interpolated at the estimate stamps inside its span. */
    private static Associated interpolate(Trajectory ref, Trajectory est, EvaluationOptions o, boolean planar,
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
        double[] sampling = referenceSampling(ref, spanLo, spanHi, par);
        double limit = o.maxGap().limitS(ref);
        if (sampling[0] > limit) {
            return null; // a reference gap longer than the limit: the general path drops and counts
        }
        InterpolatedReference interp = planar ? InterpolatedReference.planar((PlanarTrajectory) ref, m)
                : InterpolatedReference.spatial((SpatialTrajectory) ref, m);
        int first = k0;
        par.forEachChunk(m, (c, from, to) -> interp.fill(k -> est.t(first + k) + off, from, to));
        return new Associated(AssociatedColumns.interpolated(ref, est, interp, k0, m, off), ne - m, 0, sampling[0],
                sampling[1], limit);
    }

    /** evo's nearest matching, as index maps. */
    private static Associated nearest(Trajectory ref, Trajectory est, EvaluationOptions o, String refName,
            String estName) {
        TimeAssociation.NearestPairs np = TimeAssociation.nearestPairs(ref, est, new AssociationOptions(
                o.association(), o.maxDiffS(), o.tOffsetS(), o.overlap(), o.maxGap()), refName, estName);
        int m = np.count();
        if (m < 2) {
            return null;
        }
        int first = np.reference()[0];
        int last = np.reference()[m - 1];
        return new Associated(AssociatedColumns.matched(ref, est, np.reference(), np.estimate(), m, o.tOffsetS()),
                est.size() - np.distinctEstimate(), ref.size() - np.distinctReference(),
                ReferenceSampling.maxGap(ref, first, last), ReferenceSampling.maxAcceleration(ref, first, last),
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

    /** The RPE pairs of one pair-selection rule, with the sums behind the mean horizon. */
    private abstract static class PairRule {
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

    /**
     * Reference path lengths between the poses of pairs met in order (i and j never decrease):
     * two running sums of {@link AssociatedColumns#hop}s from a start pose, to i and to j.
     */
    private static final class PathSpan {
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

    /** The RPE pairs of the walk's rules, walked again at each reading (pairs that chain, e.g. consecutive). */
    private static final class Walk extends PairRule {
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

    /**
     * RPE in frames between poses d apart, not overlapping: pair p is (p d, p d + d), so chunks
     * of pairs are independent (evo's default, {@code --delta 1 --delta_unit f}).
     */
    private static final class Stride extends PairRule {
        private final int d;
        private final Parallelism par;

        Stride(AssociatedColumns poses, int d, Parallelism par) {
            super(poses);
            this.d = d;
            this.par = par;
            int m = poses.size();
            pairs = m > d ? (m - 1) / d : 0; // the p with p d + d < m
            int chunks = Parallelism.chunks(pairs);
            double[] chunkS = new double[chunks];
            double[] chunkM = new double[chunks];
            par.forEachChunk(pairs, (c, from, to) -> {
                double sum = 0;
                double len = 0;
                PathSpan path = new PathSpan(poses, from * d);
                for (int p = from; p < to; p++) {
                    int i = p * d;
                    sum += poses.stamp(i + d) - poses.stamp(i);
                    len += path.between(i, i + d);
                }
                chunkS[c] = sum;
                chunkM[c] = len;
            });
            for (int c = 0; c < chunks; c++) {
                sumS += chunkS[c];
                sumM += chunkM[c];
            }
        }

        @Override
        void errorsInto(double[] trans, double[] rot) {
            par.forEachChunk(pairs, (c, from, to) -> {
                AssociatedColumns.Scratch s = new AssociatedColumns.Scratch();
                for (int p = from; p < to; p++) {
                    poses.rpe(p * d, p * d + d, s);
                    trans[p] = s.transError;
                    rot[p] = s.rotError;
                }
            });
        }
    }

    /**
     * RPE from every start pose i = 0, 1, ...: pair p starts at pose p, so chunks of start
     * poses are independent. The pairs end at the first start pose without a partner.
     */
    private static final class EveryStart extends PairRule {
        private final double delta;
        private final boolean frames;
        private final Parallelism par;
        private final int m;

        EveryStart(AssociatedColumns poses, double delta, RpeUnit unit, Parallelism par) {
            super(poses);
            this.delta = delta;
            this.frames = unit == RpeUnit.FRAMES;
            this.par = par;
            this.m = poses.size();
            int chunks = Parallelism.chunks(m);
            int[] firstWithout = new int[chunks];
            double[] chunkS = new double[chunks];
            double[] chunkM = new double[chunks];
            par.forEachChunk(m, (c, from, to) -> {
                double s = 0;
                double len = 0;
                PathSpan path = new PathSpan(poses, from);
                int j = frames ? from : firstPartner(from);
                int i = from;
                for (; i < to; i++) {
                    j = partner(i, j);
                    if (j >= m || j == i && !frames) {
                        break;
                    }
                    s += poses.stamp(j) - poses.stamp(i);
                    len += path.between(i, j);
                }
                firstWithout[c] = i;
                chunkS[c] = s;
                chunkM[c] = len;
            });
            pairs = m;
            for (int c = 0; c < chunks; c++) {
                sumS += chunkS[c];
                sumM += chunkM[c];
                if (firstWithout[c] < Math.min((long) (c + 1) * Parallelism.CHUNK, m)) {
                    pairs = firstWithout[c];
                    break;
                }
            }
        }

        /** @return the partner of start pose i, given the partner j of an earlier start in the same chunk */
        private int partner(int i, int j) {
            if (frames) {
                long k = (long) i + (int) delta;
                return k >= m ? m : (int) k;
            }
            double target = poses.stamp(i) + delta;
            j = Math.max(i, j);
            while (j < m && poses.stamp(j) < target) {
                j++;
            }
            return j;
        }

        /** @return the first pose j &gt;= i with t_j &gt;= t_i + delta (s), or m (binary search) */
        private int firstPartner(int i) {
            double target = poses.stamp(i) + delta;
            int lo = i;
            int hi = m;
            while (lo < hi) {
                int mid = (lo + hi) >>> 1;
                if (poses.stamp(mid) < target) {
                    lo = mid + 1;
                } else {
                    hi = mid;
                }
            }
            return lo;
        }

        @Override
        void errorsInto(double[] trans, double[] rot) {
            par.forEachChunk(pairs, (c, from, to) -> {
                AssociatedColumns.Scratch s = new AssociatedColumns.Scratch();
                int j = frames ? from : firstPartner(from);
                for (int i = from; i < to; i++) {
                    j = partner(i, j);
                    poses.rpe(i, j, s);
                    trans[i] = s.transError;
                    rot[i] = s.rotError;
                }
            });
        }
    }

    /** Index pairs on the associated poses, by the rules of the general path ({@code PairIndices}). */
    private static final class PairWalk {
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

    /** What the evaluator computed; {@link Evaluator} turns it into the report. */
    record ReportParts(int matched, int dropped, int droppedReference, double maxGapS, double aMaxMps2,
            double gapLimitS, AlignmentTransform alignment, List<EvaluationReport.Warning> alignmentWarnings,
            ErrorStatistics ateTrans, ErrorStatistics ateRot, ErrorStatistics rpeTrans, ErrorStatistics rpeRot,
            int pairs, double meanHorizonS, double meanHorizonM, Coverage coverage) {
    }
}
