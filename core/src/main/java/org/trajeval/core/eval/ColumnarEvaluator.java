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
 * every RPE pair and every ATE pose is computed once. A caller that hands over an interpolated planar
 * pair's reference ({@code consumeReference}) saves the last three (24 B per pose): the reference's own
 * x, y and yaw columns, which nothing reads once the interpolated columns are filled (the coverage
 * reads its stamps only), serve as the two error arrays and the kept ATE rotations.
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

    /**
     * @param consumeReference true when the caller will not use {@code reference} again: its x, y and
     *     yaw columns may then be overwritten ({@link #handedOverColumns})
     * @return the report's parts, or {@code null} when the general path must decide (refusals, edge
     *     cases; the reference is then untouched)
     */
    static ReportParts evaluate(Trajectory reference, Trajectory estimate, EvaluationOptions o, String refName,
            String estName, Parallelism par, boolean consumeReference) {
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
        // the error arrays are the handed-over reference's columns, or are allocated (zeroed: page
        // faults) beside the fit's covariance pass
        double[][] handed = consumeReference ? handedOverColumns(reference, estimate, o, m) : null;
        double[][] errors = new double[2][];
        if (handed != null) {
            errors[0] = handed[0];
            errors[1] = handed[1];
            pairs.keepPlanarRotationsIn(handed[2]);
        }
        ColumnarAlignment fit = ColumnarAlignment.fit(pairs, o, planar, estName, par, () -> {
            if (handed == null) {
                errors[0] = new double[m];
                errors[1] = new double[m];
            }
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

    /**
     * @return the reference's x, y and yaw columns to serve as the translation errors, the rotation
     *     errors and the kept ATE rotations of m pairs, or null when they may not: only for the
     *     interpolated association of a planar reference (whose columns nothing reads after the
     *     interpolation) that shares no column with the estimate and whose columns hold m values
     */
    static double[][] handedOverColumns(Trajectory reference, Trajectory estimate, EvaluationOptions o, int m) {
        if (o.association() != AssociationMethod.INTERPOLATE || !(reference instanceof PlanarTrajectory r)
                || !(estimate instanceof PlanarTrajectory e) || r.sharesColumnsWith(e)) {
            return null;
        }
        double[][] c = r.handOverColumns();
        return c[0].length >= m && c[1].length >= m && c[2].length >= m ? c : null;
    }

    /** What the evaluator computed; {@link Evaluator} turns it into the report. */
    record ReportParts(int matched, int dropped, int droppedReference, double maxGapS, double aMaxMps2,
            double gapLimitS, AlignmentTransform alignment, List<EvaluationReport.Warning> alignmentWarnings,
            ErrorStatistics ateTrans, ErrorStatistics ateRot, ErrorStatistics rpeTrans, ErrorStatistics rpeRot,
            int pairs, double meanHorizonS, double meanHorizonM, Coverage coverage) {
    }
}
