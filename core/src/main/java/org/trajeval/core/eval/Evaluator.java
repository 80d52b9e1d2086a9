package org.trajeval.core.eval;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.Version;
import org.trajeval.core.align.Alignment;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.assoc.AssociatedPoses;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.AssociationOptions;
import org.trajeval.core.assoc.ClockOffset;
import org.trajeval.core.assoc.ReferenceGap;
import org.trajeval.core.metric.Coverage;
import org.trajeval.core.metric.ExtraMetrics;
import org.trajeval.core.assoc.TimeAssociation;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.metric.AbsoluteTrajectoryError;
import org.trajeval.core.metric.AteResult;
import org.trajeval.core.metric.DriftResult;
import org.trajeval.core.metric.LengthNormalisedDrift;
import org.trajeval.core.metric.RelativePoseError;
import org.trajeval.core.metric.RpeOptions;
import org.trajeval.core.metric.RpeResult;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.Plane;
import org.trajeval.core.traj.PlaneProjection;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.PoseSequence;
import org.trajeval.core.stats.ErrorStatistics;
import org.trajeval.core.traj.Trajectory;

/**
 * Scores an estimate against a reference: optional projection before alignment, time
 * association, alignment applied to whole poses, optional projection after alignment, then
 * ATE, RPE and drift.
 */
public final class Evaluator {
    private Evaluator() {
    }

    /**
     * Evaluates one pair and returns the report (what {@code trajeval eval --json} prints).
     *
     * @throws InputException when the pair cannot be scored (no overlap, too few poses,
     *     degenerate alignment)
     */
    public static EvaluationReport evaluate(LoadedTrajectory reference, LoadedTrajectory estimate,
            EvaluationOptions options) {
        return evaluate(reference, estimate, options, Parallelism.SEQUENTIAL);
    }

    /**
     * As {@link #evaluate(LoadedTrajectory, LoadedTrajectory, EvaluationOptions)}, with the
     * element-wise passes of the columnar evaluator (interpolation, errors, RPE pairs) spread over
     * the given threads. The numbers do not depend on the thread count.
     */
    public static EvaluationReport evaluate(LoadedTrajectory reference, LoadedTrajectory estimate,
            EvaluationOptions options, Parallelism parallelism) {
        return evaluate(reference, estimate, options, parallelism, false);
    }

    /**
     * As {@link #evaluate(LoadedTrajectory, LoadedTrajectory, EvaluationOptions, Parallelism)} (the
     * same report, bit for bit) for a caller that owns the pair and never uses {@code reference}
     * again: the reference is consumed, i.e. for an interpolated planar pair its x, y and yaw
     * columns are overwritten by the errors instead of three arrays allocated (24 B per pose less at
     * the peak). Only its stamps and size stay valid. With {@code --t-offset auto} (several
     * evaluations of the pair) nothing is consumed.
     */
    public static EvaluationReport evaluateConsumingReference(LoadedTrajectory reference,
            LoadedTrajectory estimate, EvaluationOptions options, Parallelism parallelism) {
        return evaluate(reference, estimate, options, parallelism, true);
    }

    private static EvaluationReport evaluate(LoadedTrajectory reference, LoadedTrajectory estimate,
            EvaluationOptions options, Parallelism parallelism, boolean consumeReference) {
        if (options.timeOffset() == TimeOffset.AUTO) {
            return withEstimatedOffset(reference, estimate, options, parallelism);
        }
        if (ColumnarEvaluator.applies(reference, estimate, options)) {
            ColumnarEvaluator.ReportParts p = ColumnarEvaluator.evaluate(reference.trajectory(),
                    estimate.trajectory(), options, reference.source(), estimate.source(), parallelism,
                    consumeReference);
            if (p != null) {
                return report(reference, estimate, options, p.matched(), p.dropped(), p.droppedReference(),
                        p.maxGapS(), p.aMaxMps2(), p.alignment(), p.ateTrans(), p.ateRot(), p.rpeTrans(), p.rpeRot(),
                        p.pairs(), p.meanHorizonS(), p.meanHorizonM(), null, p.gapLimitS(), List.of(), p.coverage(),
                        p.alignmentWarnings());
            }
        }
        return run(reference, estimate, options).report();
    }

    /** Largest clock offset {@code --t-offset auto} searches, either sign (s). */
    public static final double MAX_AUTO_OFFSET_S = 2.0;

    /**
     * {@code --t-offset auto}: the offset at the peak of the angular-speed cross-correlation
     * ({@link ClockOffset}), refined by a golden-section search of the ATE RMSE within
     * +-max(uncertainty, grid step) around it; the report gives both.
     */
    private static EvaluationReport withEstimatedOffset(LoadedTrajectory reference, LoadedTrajectory estimate,
            EvaluationOptions options, Parallelism parallelism) {
        ClockOffset.Estimate e = ClockOffset.estimate(reference.trajectory(), estimate.trajectory(), MAX_AUTO_OFFSET_S);
        if (e == null) {
            throw new InputException(estimate.source(), 0, "t", InputProblem.NO_OVERLAP, String.format(Locale.ROOT,
                    "--t-offset auto: the trajectories do not overlap enough to estimate a clock offset within "
                    + "+-%.1f s, or do not rotate; give the offset with --t-offset S", MAX_AUTO_OFFSET_S), null);
        }
        EvaluationOptions given = options.withTimeOffset(TimeOffset.GIVEN);
        double w = Math.max(e.uncertaintyS(), e.stepS());
        double a = e.offsetS() - w;
        double b = e.offsetS() + w;
        double g = (Math.sqrt(5.0) - 1.0) / 2.0;
        double c = b - g * (b - a);
        double d = a + g * (b - a);
        double fc = ateAt(reference, estimate, given, c, parallelism);
        double fd = ateAt(reference, estimate, given, d, parallelism);
        for (int i = 0; i < 24; i++) {
            if (fc <= fd) {
                b = d;
                d = c;
                fd = fc;
                c = b - g * (b - a);
                fc = ateAt(reference, estimate, given, c, parallelism);
            } else {
                a = c;
                c = d;
                fc = fd;
                d = a + g * (b - a);
                fd = ateAt(reference, estimate, given, d, parallelism);
            }
        }
        double best = Double.isFinite(Math.min(fc, fd)) ? 0.5 * (a + b) : e.offsetS();
        EvaluationReport r = evaluate(reference, estimate, given.withTOffsetS(best), parallelism);
        return r.withAssociation(r.association().withOffset(best, new EvaluationReport.OffsetEstimate(e.offsetS(),
                e.uncertaintyS(), e.correlation(), "angular-speed cross-correlation, refined on ATE")));
    }

    private static double ateAt(LoadedTrajectory reference, LoadedTrajectory estimate, EvaluationOptions given,
            double offsetS, Parallelism parallelism) {
        try {
            Double rmse = evaluate(reference, estimate, given.withTOffsetS(offsetS), parallelism).ate().transM().rmse();
            return rmse == null ? Double.POSITIVE_INFINITY : rmse;
        } catch (InputException ex) {
            return Double.POSITIVE_INFINITY;
        }
    }

    /** Evaluates one pair and returns the report with the per-pose data behind it. */
    public static Evaluation run(LoadedTrajectory reference, LoadedTrajectory estimate, EvaluationOptions options) {
        if (options.timeOffset() == TimeOffset.AUTO) {
            EvaluationReport r = withEstimatedOffset(reference, estimate, options, Parallelism.SEQUENTIAL);
            Evaluation e = run(reference, estimate, options.withTimeOffset(TimeOffset.GIVEN)
                    .withTOffsetS(r.association().tOffsetS()));
            return new Evaluation(e.report().withAssociation(r.association()), e.associated(), e.reference(),
                    e.alignedEstimate(), e.alignment(), e.ate(), e.rpe(), e.drift());
        }
        Trajectory ref = reference.trajectory();
        Trajectory est = estimate.trajectory();
        if (options.projection() == PlanarProjection.XY_BEFORE_ALIGNMENT) {
            ref = ref.toPlanar();
            est = est.toPlanar();
        }
        AssociatedPoses assoc = TimeAssociation.compute(ref, est, new AssociationOptions(options.association(),
                options.maxDiffS(), options.tOffsetS(), options.overlap(), options.maxGap()), reference.source(),
                estimate.source());
        AlignmentTransform alignment = Alignment.fit(options.alignment(), assoc.reference(), assoc.estimate(),
                options.nToAlign(), estimate.source());
        boolean planarData = ref instanceof PlanarTrajectory && est instanceof PlanarTrajectory;
        List<EvaluationReport.Warning> alignmentWarnings = AlignmentCheck.check(alignment, assoc.reference(),
                assoc.estimate(), assoc.size(), planarData);
        PoseSequence refPoses = assoc.reference();
        PoseSequence estPoses = alignment.apply(assoc.estimate());
        if (options.projection() == PlanarProjection.XY_AFTER_ALIGNMENT
                || options.projection() == PlanarProjection.XZ_AFTER_ALIGNMENT) {
            Plane plane = options.projection() == PlanarProjection.XY_AFTER_ALIGNMENT ? Plane.XY : Plane.XZ;
            refPoses = PlaneProjection.project(refPoses, plane);
            estPoses = PlaneProjection.project(estPoses, plane);
        }
        AteResult ate = AbsoluteTrajectoryError.compute(refPoses, estPoses);
        if (assoc.size() < 2) {
            throw new InputException(estimate.source(), 0, null, InputProblem.TOO_FEW_POSES,
                    "RPE needs at least 2 associated poses, only " + assoc.size() + " could be paired with "
                            + reference.source(), null);
        }
        RpeResult rpe = RelativePoseError.compute(refPoses, estPoses, assoc.timestamps(),
                new RpeOptions(options.rpeDelta(), options.rpeUnit(), options.pairSelection(), options.pairsFrom()));
        DriftResult drift = options.drift() == null ? null
                : LengthNormalisedDrift.compute(refPoses, estPoses, options.drift());
        double[] stamps = assoc.timestamps();
        Coverage coverage = Coverage.compute(k -> stamps[k], stamps.length, ref.t(0), ref.t(ref.size() - 1));
        EvaluationReport report = report(reference, estimate, options, assoc.size(), assoc.droppedEstimate(),
                assoc.droppedReference(), assoc.maxGapS(), assoc.aMaxMps2(), alignment, ate.trans(), ate.rot(),
                rpe.trans(), rpe.rot(), rpe.pairs(), rpe.meanHorizonS(), rpe.meanHorizonM(), drift,
                assoc.gapLimitS(), assoc.gaps(), coverage, alignmentWarnings);
        if (options.extraMetrics()) {
            // the speed horizon is the RPE's own (its mean in seconds over the pairs used), 1 s without pairs
            double h = Double.isFinite(rpe.meanHorizonS()) && rpe.meanHorizonS() > 0 ? rpe.meanHorizonS() : 1.0;
            ExtraMetrics x = ExtraMetrics.compute(refPoses, estPoses, assoc.timestamps(), h);
            report = new EvaluationReport(report.schema(), report.schemaVersion(), report.version(),
                    report.convention(), report.inputs(), report.association(), report.alignment(), report.ate(),
                    report.rpe(), report.drift(), report.coverage(), report.warnings(), report.timeBase(),
                    new EvaluationReport.Extra(EvaluationReport.Stats.of(x.transX()),
                            EvaluationReport.Stats.of(x.transY()), EvaluationReport.Stats.of(x.transZ()),
                            EvaluationReport.Stats.of(x.heading()), EvaluationReport.Stats.of(x.speed()), h));
        }
        return new Evaluation(report, assoc, refPoses, estPoses, alignment, ate, rpe, drift);
    }

    private static EvaluationReport report(LoadedTrajectory reference, LoadedTrajectory estimate,
            EvaluationOptions o, int matched, int dropped, int droppedReference, double maxGapS, double aMaxMps2,
            AlignmentTransform alignment, ErrorStatistics ateTrans, ErrorStatistics ateRot, ErrorStatistics rpeTrans,
            ErrorStatistics rpeRot, int pairs, double meanHorizonS, double meanHorizonM, DriftResult drift,
            double gapLimitS, List<ReferenceGap> gaps, Coverage coverage,
            List<EvaluationReport.Warning> alignmentWarnings) {
        // KITTI poses without times files are stamped 0, 1, 2, ...: their "seconds" are frames
        String timeBase = reference.indexTimestamps() && estimate.indexTimestamps() ? "frames" : "s";
        boolean interpolating = o.association() != AssociationMethod.NEAREST;
        boolean gapLimited = o.association() == AssociationMethod.INTERPOLATE;
        List<EvaluationReport.Gap> gapInfo = new ArrayList<>();
        int droppedInGaps = 0;
        for (ReferenceGap g : gaps) {
            droppedInGaps += g.dropped();
            if (gapInfo.size() < EvaluationReport.AssociationInfo.MAX_GAPS_LISTED) {
                gapInfo.add(new EvaluationReport.Gap(g.startS(), g.endS(), g.lengthS(), g.dropped()));
            }
        }
        EvaluationReport.AssociationInfo associationInfo = new EvaluationReport.AssociationInfo(
                lower(o.association()), matched, dropped, droppedReference, o.maxDiffS(),
                o.tOffsetS(), lower(o.overlap()), maxGapS, interpolating ? aMaxMps2 : null,
                interpolating ? aMaxMps2 * maxGapS * maxGapS / 8.0 : null,
                gapLimited && Double.isFinite(gapLimitS) ? gapLimitS : null, droppedInGaps, gapInfo, null);
        List<EvaluationReport.Warning> warnings = new ArrayList<>(alignmentWarnings);
        if (droppedInGaps > 0) {
            ReferenceGap longest = gaps.get(0);
            for (ReferenceGap g : gaps) {
                longest = g.lengthS() > longest.lengthS() ? g : longest;
            }
            warnings.add(new EvaluationReport.Warning("poses_dropped_in_reference_gaps", String.format(Locale.ROOT,
                    "%d estimate poses lie inside %d reference gaps longer than the max gap %.4g s and were dropped "
                    + "(longest gap %.3f s, from %.3f s to %.3f s); raise --max-gap (max_gap_s) to interpolate "
                    + "across such gaps", droppedInGaps, gaps.size(), gapLimitS, longest.lengthS(), longest.startS(),
                    longest.endS())));
        }
        if (o.nToAlign() > 0 && alignment.posesUsed() < o.nToAlign()) {
            warnings.add(new EvaluationReport.Warning("n_to_align_clamped", String.format(Locale.ROOT,
                    "n-to-align %d is more than the %d associated poses: the alignment was fitted on all %d",
                    o.nToAlign(), alignment.posesUsed(), alignment.posesUsed())));
        }
        if (pairs == 0) {
            warnings.add(new EvaluationReport.Warning("no_rpe_pairs", String.format(Locale.ROOT,
                    "no RPE pair: the horizon %s %s is longer than the associated trajectory; choose a shorter "
                    + "--rpe-delta (rpe_delta)", o.rpeDelta(), o.rpeUnit().symbol())));
        }
        EvaluationReport.CoverageInfo coverageInfo = new EvaluationReport.CoverageInfo(coverage.fraction(),
                coverage.longestGapS(), coverage.longestGapStartS(), coverage.uncoveredS(), coverage.referenceSpanS());
        EvaluationReport.AlignmentInfo alignmentInfo = new EvaluationReport.AlignmentInfo(lower(alignment.model()),
                alignment.rotationRows(), alignment.translation(), alignment.scale(), alignment.posesUsed());
        EvaluationReport.Rpe rpeInfo = new EvaluationReport.Rpe(EvaluationReport.Stats.of(rpeTrans),
                EvaluationReport.Stats.of(rpeRot), pairs, o.rpeDelta(),
                o.rpeUnit() == RpeUnit.SECONDS && timeBase.equals("frames") ? "frames" : o.rpeUnit().symbol(),
                lower(o.pairSelection()), lower(o.pairsFrom()), finiteOrNull(meanHorizonS),
                finiteOrNull(meanHorizonM));
        EvaluationReport.Drift driftInfo = null;
        if (drift != null) {
            List<EvaluationReport.DriftAtLength> per = new ArrayList<>();
            for (DriftResult.AtLength a : drift.perLength()) {
                per.add(new EvaluationReport.DriftAtLength(a.lengthM(), finiteOrNull(a.transPct()),
                        finiteOrNull(a.rotDegPerM()), a.segments()));
            }
            driftInfo = new EvaluationReport.Drift(finiteOrNull(drift.transPct()), finiteOrNull(drift.rotDegPerM()),
                    drift.segments(), drift.stepFrames(), per, drift.pathLengthM());
            double shortest = Double.POSITIVE_INFINITY;
            for (DriftResult.AtLength a : drift.perLength()) {
                shortest = Math.min(shortest, a.lengthM());
            }
            if (drift.segments() == 0) {
                warnings.add(new EvaluationReport.Warning("drift_path_too_short", String.format(Locale.ROOT,
                        "no drift: the reference path is %.1f m long, shorter than the shortest segment length "
                        + "%.4g m (with its start every %d frames); give shorter lengths with --drift-lengths",
                        drift.pathLengthM(), shortest, drift.stepFrames())));
            }
        }

        return new EvaluationReport(EvaluationReport.SCHEMA, EvaluationReport.SCHEMA_VERSION, Version.TOOL,
                lower(o.convention()),
                new EvaluationReport.Inputs(input(reference), input(estimate)), associationInfo, alignmentInfo,
                new EvaluationReport.Ate(EvaluationReport.Stats.of(ateTrans), EvaluationReport.Stats.of(ateRot)),
                rpeInfo, driftInfo, coverageInfo, warnings, timeBase, null);
    }

    private static EvaluationReport.InputInfo input(LoadedTrajectory t) {
        return new EvaluationReport.InputInfo(t.source(), t.format().id(), t.formatReason(), t.trajectory().size(),
                t.sha256());
    }

    private static Double finiteOrNull(double v) {
        return Double.isFinite(v) ? v : null;
    }

    private static String lower(Enum<?> e) {
        return e.name().toLowerCase(Locale.ROOT);
    }
}
