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
import org.trajeval.core.assoc.ReferenceGap;
import org.trajeval.core.metric.Coverage;
import org.trajeval.core.assoc.TimeAssociation;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.metric.AbsoluteTrajectoryError;
import org.trajeval.core.metric.AteResult;
import org.trajeval.core.metric.DriftResult;
import org.trajeval.core.metric.LengthNormalisedDrift;
import org.trajeval.core.metric.RelativePoseError;
import org.trajeval.core.metric.RpeOptions;
import org.trajeval.core.metric.RpeResult;
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
     * element-wise passes of the planar fast path (interpolation, errors, RPE pairs) spread over
     * the given threads. The numbers do not depend on the thread count.
     */
    public static EvaluationReport evaluate(LoadedTrajectory reference, LoadedTrajectory estimate,
            EvaluationOptions options, Parallelism parallelism) {
        if (PlanarEvaluator.applies(reference, estimate, options)) {
            PlanarEvaluator.ReportParts p = PlanarEvaluator.evaluate((PlanarTrajectory) reference.trajectory(),
                    (PlanarTrajectory) estimate.trajectory(), options, estimate.source(), parallelism);
            if (p != null) {
                Trajectory ref = reference.trajectory();
                Trajectory est = estimate.trajectory();
                double off = options.tOffsetS();
                int k0 = 0;
                while (est.t(k0) + off < ref.t(0)) {
                    k0++;
                }
                int first = k0;
                Coverage coverage = Coverage.compute(k -> est.t(first + k) + off, p.matched(), ref.t(0),
                        ref.t(ref.size() - 1));
                return report(reference, estimate, options, p.matched(), p.dropped(), 0, p.maxGapS(), p.aMaxMps2(),
                        p.alignment(), p.ateTrans(), p.ateRot(), p.rpeTrans(), p.rpeRot(), p.pairs(),
                        p.meanHorizonS(), p.meanHorizonM(), null, options.maxGap().limitS(ref), List.of(), coverage);
            }
        }
        return run(reference, estimate, options).report();
    }

    /** Evaluates one pair and returns the report with the per-pose data behind it. */
    public static Evaluation run(LoadedTrajectory reference, LoadedTrajectory estimate, EvaluationOptions options) {
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
                assoc.gapLimitS(), assoc.gaps(), coverage);
        return new Evaluation(report, assoc, refPoses, estPoses, alignment, ate, rpe, drift);
    }

    private static EvaluationReport report(LoadedTrajectory reference, LoadedTrajectory estimate,
            EvaluationOptions o, int matched, int dropped, int droppedReference, double maxGapS, double aMaxMps2,
            AlignmentTransform alignment, ErrorStatistics ateTrans, ErrorStatistics ateRot, ErrorStatistics rpeTrans,
            ErrorStatistics rpeRot, int pairs, double meanHorizonS, double meanHorizonM, DriftResult drift,
            double gapLimitS, List<ReferenceGap> gaps, Coverage coverage) {
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
                gapLimited && Double.isFinite(gapLimitS) ? gapLimitS : null, droppedInGaps, gapInfo);
        List<EvaluationReport.Warning> warnings = new ArrayList<>();
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
        EvaluationReport.CoverageInfo coverageInfo = new EvaluationReport.CoverageInfo(coverage.fraction(),
                coverage.longestGapS(), coverage.longestGapStartS(), coverage.uncoveredS(), coverage.referenceSpanS());
        EvaluationReport.AlignmentInfo alignmentInfo = new EvaluationReport.AlignmentInfo(lower(alignment.model()),
                alignment.rotationRows(), alignment.translation(), alignment.scale(), alignment.posesUsed());
        EvaluationReport.Rpe rpeInfo = new EvaluationReport.Rpe(EvaluationReport.Stats.of(rpeTrans),
                EvaluationReport.Stats.of(rpeRot), pairs, o.rpeDelta(), o.rpeUnit().symbol(),
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
                    drift.segments(), drift.stepFrames(), per);
        }
        return new EvaluationReport(EvaluationReport.SCHEMA, EvaluationReport.SCHEMA_VERSION, Version.TOOL,
                lower(o.convention()),
                new EvaluationReport.Inputs(input(reference), input(estimate)), associationInfo, alignmentInfo,
                new EvaluationReport.Ate(EvaluationReport.Stats.of(ateTrans), EvaluationReport.Stats.of(ateRot)),
                rpeInfo, driftInfo, coverageInfo, warnings);
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
