package org.trajeval.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.eval.PlanarProjection;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.metric.DriftOptions;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.PairsFrom;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.traj.PlanarTrajectory;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code trajeval eval REF EST}: scores one estimate against one reference. */
@Command(name = "eval", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Scores an estimate trajectory against a reference (ground truth): time association, "
            + "alignment applied to whole poses, ATE, RPE and optional KITTI drift.",
            "Units: positions m, angles rad, times s; report keys name their unit (trans_m, rot_rad, max_gap_s)."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success", "1:internal error (a bug; rerun with --verbose)",
            "2:bad input or usage (one line names file, line and what was expected)"})
public final class EvalCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "REF", description = "Reference (ground-truth) trajectory file.")
    Path reference;

    @Parameters(index = "1", paramLabel = "EST", description = "Estimated trajectory file.")
    Path estimate;

    @Mixin
    InputOptions input = new InputOptions();

    @Option(names = "--convention", paramLabel = "lesson|evo|kitti",
            description = "Preset of rules (default: ${DEFAULT-VALUE}). lesson: interpolated association, crop, "
                    + "se2/se3 alignment, RPE over 1 s for every start pose; evo: nearest within 0.01 s, no "
                    + "alignment, RPE over 1 frame; kitti: index pairing, drift as the headline. Explicit options "
                    + "override the preset.", defaultValue = "lesson", converter = Enums.ConventionConverter.class)
    Convention convention;

    @Option(names = "--association", paramLabel = "interpolate|nearest|nearest-interpolated",
            description = "interpolate: the reference interpolated at the estimate stamps (lesson); nearest: evo's "
                    + "nearest stamp within --max-diff; nearest-interpolated: evo's --sync_method interpolation.",
            converter = Enums.AssociationConverter.class)
    AssociationMethod association;

    @Option(names = "--max-diff", paramLabel = "S", description = "Max timestamp difference for nearest association (s).")
    Double maxDiffS;

    @Option(names = "--t-offset", paramLabel = "S", description = "Offset added to the estimate's timestamps (s).")
    Double tOffsetS;

    @Option(names = "--overlap", paramLabel = "crop|strict", description = "Estimate poses outside the reference's "
            + "time span: crop (drop and count them; default) or strict (refuse).",
            converter = Enums.OverlapConverter.class)
    OverlapPolicy overlap;

    @Option(names = "--align", paramLabel = "none|se2|sim2|se3|sim3|origin|posyaw",
            description = "Alignment fitted on positions and applied to whole poses (default: lesson se2 for planar "
                    + "data, se3 for SE(3) data; evo and kitti none).", converter = Enums.AlignmentConverter.class)
    AlignmentModel align;

    @Option(names = "--n-to-align", paramLabel = "N", description = "Fit the alignment on the first N associated poses.")
    Integer nToAlign;

    @Option(names = "--planar", description = "Project SE(3) poses onto the ground plane xy before alignment (SE(2)).")
    boolean planar;

    @Option(names = "--project-to-plane", paramLabel = "xy|xz", description = "evo's projection after a 3D "
            + "alignment (xz for camera frames such as KITTI's).")
    String projectToPlane;

    @Option(names = "--rpe-delta", paramLabel = "D", description = "RPE horizon in --rpe-unit (default: lesson 1 s, "
            + "evo and kitti 1 frame).")
    Double rpeDelta;

    @Option(names = "--rpe-unit", paramLabel = "s|frames|m", description = "Unit of --rpe-delta: seconds, frames or "
            + "metres travelled.", converter = Enums.RpeUnitConverter.class)
    RpeUnit rpeUnit;

    @Option(names = "--all-pairs", negatable = true, description = "Use every start pose (all pairs) instead of "
            + "consecutive, non-overlapping pairs (lesson default: all pairs; evo and kitti: consecutive).")
    Boolean allPairs;

    @Option(names = "--pairs-from", paramLabel = "reference|estimate", description = "Trajectory the RPE pairs are "
            + "chosen on (default: estimate, as evo).", converter = Enums.PairsFromConverter.class)
    PairsFrom pairsFrom;

    @Option(names = "--drift", description = "Compute KITTI-style length-normalised drift (%%, deg/m).")
    boolean drift;

    @Option(names = "--drift-lengths", paramLabel = "M,M,...",
            description = "Drift segment lengths (m; default 100,200,...,800).")
    String driftLengthsText;

    @Option(names = "--drift-step", paramLabel = "FRAMES", description = "Frames between drift segment starts "
            + "(default 10).")
    Integer driftStep;

    @Option(names = "--json", description = "Print the report as one JSON object (schema trajeval.evaluation v1).")
    boolean json;

    @Option(names = "--out", paramLabel = "FILE", description = "Write the JSON report to FILE (atomically).")
    Path out;

    @Mixin
    PlotOptions plots = new PlotOptions();

    @Option(names = "--threads", paramLabel = "N", description = "Threads for reading the two files at once and "
            + "for the element-wise passes of the planar evaluation (default: ${DEFAULT-VALUE}; 1 does everything on "
            + "one thread). The numbers do not depend on it.", defaultValue = "2")
    int threads;

    @Option(names = "--verbose", description = "Print stack traces of errors.")
    boolean verbose;

    @Override
    public Integer call() {
        MemoryBudget.check(reference, estimate, Runtime.getRuntime().maxMemory());
        if (convention == Convention.EVO) {
            input.defaultDuplicates = org.trajeval.core.io.DuplicateTimestamps.KEEP;
        }
        EvaluationReport report;
        try (EvalThreads work = new EvalThreads(threads)) {
            LoadedTrajectory[] pair = work.both(input, reference, estimate);
            LoadedTrajectory ref = pair[0];
            LoadedTrajectory est = pair[1];
            if (plots.wanted()) {
                report = EvalPlots.write(ref, est, options(ref, est), plots, spec.commandLine().getErr());
            } else {
                report = Evaluator.evaluate(ref, est, options(ref, est), work.parallelism());
            }
        }
        // JSON (and Jackson's start-up) only when asked for
        String jsonText = json || out != null ? ReportJson.toJson(report) : null;
        if (out != null) {
            ReportJson.writeAtomically(out, jsonText + "\n");
        }
        PrintWriter o = spec.commandLine().getOut();
        if (json && out == null) {
            o.println(jsonText);
        } else if (!json) {
            o.print(ReportTable.render(report));
        }
        o.flush();
        return ExitCodes.OK;
    }

    EvaluationOptions options(LoadedTrajectory ref, LoadedTrajectory est) {
        boolean planarData = planar
                || (ref.trajectory() instanceof PlanarTrajectory && est.trajectory() instanceof PlanarTrajectory);
        EvaluationOptions o = EvaluationOptions.preset(convention, planarData);
        if (association != null) {
            o = o.withAssociation(association);
        }
        if (maxDiffS != null) {
            o = o.withMaxDiffS(maxDiffS);
        }
        if (tOffsetS != null) {
            o = o.withTOffsetS(tOffsetS);
        }
        if (overlap != null) {
            o = o.withOverlap(overlap);
        }
        if (align != null) {
            o = o.withAlignment(align);
        }
        if (nToAlign != null) {
            o = o.withNToAlign(nToAlign);
        }
        if (planar && projectToPlane != null) {
            throw new IllegalArgumentException("--planar (projection before alignment) and --project-to-plane "
                    + "(after alignment) exclude each other; choose one");
        }
        if (planar) {
            o = o.withProjection(PlanarProjection.XY_BEFORE_ALIGNMENT);
        } else if (projectToPlane != null) {
            o = o.withProjection(switch (projectToPlane.toLowerCase(Locale.ROOT)) {
                case "xy" -> PlanarProjection.XY_AFTER_ALIGNMENT;
                case "xz" -> PlanarProjection.XZ_AFTER_ALIGNMENT;
                default -> throw new IllegalArgumentException("--project-to-plane must be xy or xz, found \""
                        + projectToPlane + "\"");
            });
        }
        if (rpeDelta != null || rpeUnit != null) {
            RpeUnit unit = rpeUnit != null ? rpeUnit : o.rpeUnit();
            double delta = rpeDelta != null ? rpeDelta : (unit == o.rpeUnit() ? o.rpeDelta() : 1.0);
            o = o.withRpe(delta, unit);
        }
        if (allPairs != null) {
            o = o.withPairSelection(allPairs ? PairSelection.ALL_PAIRS : PairSelection.CONSECUTIVE);
        }
        if (pairsFrom != null) {
            o = o.withPairsFrom(pairsFrom);
        }
        double[] driftLengths = driftLengthsText == null ? null : numbers("--drift-lengths", driftLengthsText);
        if (drift || driftLengths != null || driftStep != null) {
            DriftOptions base = DriftOptions.KITTI;
            o = o.withDrift(new DriftOptions(driftLengths != null ? driftLengths : base.segmentLengthsM(),
                    driftStep != null ? driftStep : base.stepFrames()));
        }
        return o;
    }

    private static double[] numbers(String option, String text) {
        String[] parts = text.split(",");
        double[] v = new double[parts.length];
        for (int i = 0; i < parts.length; i++) {
            try {
                v[i] = Double.parseDouble(parts[i].trim());
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException(option + " expects numbers separated by commas (m), found \""
                        + parts[i].trim() + "\"");
            }
        }
        return v;
    }

    /** @return the format names accepted by --format */
    static String formats() {
        StringBuilder sb = new StringBuilder("auto");
        for (TrajectoryFormat f : TrajectoryFormat.values()) {
            sb.append('|').append(f.id());
        }
        return sb.toString();
    }
}
