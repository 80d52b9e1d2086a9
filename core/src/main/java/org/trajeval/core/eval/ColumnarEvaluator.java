package org.trajeval.core.eval;

import java.util.List;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.metric.Coverage;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.stats.ErrorStatistics;
import org.trajeval.core.traj.PlanarTrajectory;
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
 * SE(3) 20 B per pose: its bracket and the ATE rotation errors the RPE computes; for nearest
 * matching 8 B of index maps instead, and for SE(3) pairs the ATE rotation errors the RPE computes,
 * 8 B), for planar kernels the ATE rotation errors the RPE
 * computes (8 B per pose), and two error arrays (16 B per pose) that the RPE and then the ATE fill;
 * every RPE pair and every ATE pose is computed once.
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
        ColumnarAssociation a = o.association() == AssociationMethod.INTERPOLATE
                ? ColumnarAssociation.interpolate(ref, est, o, planar, par)
                : ColumnarAssociation.nearest(ref, est, o, refName, estName, par);
        if (a == null) {
            return null;
        }
        AssociatedColumns pairs = a.pairs();
        int m = pairs.size();
        // the error arrays are allocated (zeroed: page faults) beside the fit's covariance pass
        double[][] errors = new double[2][];
        ColumnarAlignment fit = ColumnarAlignment.fit(pairs, o, planar, estName, par, () -> {
            errors[0] = new double[m];
            errors[1] = new double[m];
        });
        AlignmentTransform tf = fit.transform();
        pairs.align(tf);

        // ---- errors and statistics: each RPE pair and each ATE pose computed once, translation
        // into one array and rotation into another; the ATE reuses the arrays of the RPE. Each
        // statistic is one serial pass over its own array: two of them (and the coverage) run side by side
        PairRule rule = PairRule.of(pairs, o, par);
        double[] trans = errors[0];
        double[] rot = errors[1];
        rule.errorsInto(trans, rot);
        int count = rule.pairs();
        ErrorStatistics[] stats = new ErrorStatistics[4];
        Coverage[] coverage = new Coverage[1];
        Trajectory r = ref;
        par.all(() -> stats[2] = ErrorStatistics.ofInPlace(trans, count),
                () -> stats[3] = ErrorStatistics.ofInPlace(rot, count),
                () -> coverage[0] = Coverage.compute(pairs::stamp, m, r.t(0), r.t(r.size() - 1)));
        par.forEachChunk(m, (c, from, to) -> {
            pairs.ateInto(from, to, trans, rot, new AssociatedColumns.Scratch());
        });
        par.all(() -> stats[0] = ErrorStatistics.ofInPlace(trans, m), () -> stats[1] = ErrorStatistics.ofInPlace(rot, m));
        return new ReportParts(m, a.dropped(), a.droppedReference(), a.maxGapS(), a.aMaxMps2(), a.gapLimitS(), tf,
                fit.warnings(), stats[0], stats[1], stats[2], stats[3], count,
                count == 0 ? Double.NaN : rule.sumS() / count, count == 0 ? Double.NaN : rule.sumM() / count,
                coverage[0]);
    }

    /** What the evaluator computed; {@link Evaluator} turns it into the report. */
    record ReportParts(int matched, int dropped, int droppedReference, double maxGapS, double aMaxMps2,
            double gapLimitS, AlignmentTransform alignment, List<EvaluationReport.Warning> alignmentWarnings,
            ErrorStatistics ateTrans, ErrorStatistics ateRot, ErrorStatistics rpeTrans, ErrorStatistics rpeRot,
            int pairs, double meanHorizonS, double meanHorizonM, Coverage coverage) {
    }
}
