package org.trajeval.api;

import java.nio.file.Path;
import java.util.Objects;
import org.trajeval.core.InputException;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * The Java entry point of trajeval: scores an estimate against a reference (ground truth) and
 * returns the report {@code trajeval eval --json} prints, with the same numbers for the same
 * files and settings (ATE, RPE, optional drift; positions in m, angles in rad, times in s).
 *
 * <pre>{@code
 * TrajectoryEvaluator evaluator = TrajectoryEvaluator.of(Convention.LESSON);
 * EvaluationReport report = evaluator.evaluate(Path.of("truth.txt"), Path.of("estimate.txt"));
 * double ateRmseM = report.ate().transM().rmse();
 * }</pre>
 *
 * <p>Settings: a {@link Convention} (its preset, resolved per pair as {@code trajeval eval}
 * does: the lesson's se2 alignment for planar data, se3 for SE(3) data), or fully resolved
 * {@link EvaluationOptions}. Files are read with their format detected from extension and content;
 * equal timestamps are refused, except under the evo convention, which keeps them as evo does.
 *
 * <p>Thread safety: immutable; one instance may evaluate any number of pairs from any number of
 * threads at once. Each call works on the caller's thread only.
 *
 * <p>Errors: bad input (unreadable or malformed file, no overlap in time, too few poses, a
 * degenerate alignment) throws {@link InputException}, whose fields name the source, line,
 * column and problem; invalid arrays throw {@link IllegalArgumentException}.
 */
public final class TrajectoryEvaluator {
    /** The {@code inputs.*.format} of a trajectory given as arrays. */
    public static final String MEMORY_FORMAT = "memory";

    private final Convention convention;
    private final EvaluationOptions options;

    private TrajectoryEvaluator(Convention convention, EvaluationOptions options) {
        this.convention = convention;
        this.options = options;
    }

    /** @return an evaluator with a convention's preset (resolved per pair for planar or SE(3) data) */
    public static TrajectoryEvaluator of(Convention convention) {
        return new TrajectoryEvaluator(Objects.requireNonNull(convention, "convention"), null);
    }

    /** @return an evaluator with these options for every pair, whatever its data */
    public static TrajectoryEvaluator of(EvaluationOptions options) {
        Objects.requireNonNull(options, "options");
        return new TrajectoryEvaluator(options.convention(), options);
    }

    /**
     * Reads and scores two trajectory files (CSV, TUM, KITTI, EuRoC; format detected).
     *
     * @throws InputException when a file cannot be read or the pair cannot be scored
     */
    public EvaluationReport evaluate(Path reference, Path estimate) {
        ReadOptions read = ReadOptions.defaults().withDuplicates(
                convention == Convention.EVO ? DuplicateTimestamps.KEEP : DuplicateTimestamps.REFUSE);
        LoadedTrajectory ref = TrajectoryReader.read(Objects.requireNonNull(reference, "reference"), read);
        LoadedTrajectory est = TrajectoryReader.read(Objects.requireNonNull(estimate, "estimate"), read);
        return Evaluator.evaluate(ref, est, optionsFor(ref, est));
    }

    /**
     * Scores two trajectories given as arrays. The report's inputs have format
     * {@value #MEMORY_FORMAT}, the names given to {@link Poses}, and no SHA-256.
     *
     * @throws InputException when the pair cannot be scored (no overlap in time, too few poses,
     *     degenerate alignment)
     */
    public EvaluationReport evaluate(Poses reference, Poses estimate) {
        LoadedTrajectory ref = inMemory(Objects.requireNonNull(reference, "reference"));
        LoadedTrajectory est = inMemory(Objects.requireNonNull(estimate, "estimate"));
        EvaluationReport r = Evaluator.evaluate(ref, est, optionsFor(ref, est));
        return r.withInputs(new EvaluationReport.Inputs(memoryInput(r.inputs().reference()),
                memoryInput(r.inputs().estimate())));
    }

    private EvaluationOptions optionsFor(LoadedTrajectory ref, LoadedTrajectory est) {
        if (options != null) {
            return options;
        }
        boolean planarData = ref.trajectory() instanceof PlanarTrajectory
                && est.trajectory() instanceof PlanarTrajectory;
        return EvaluationOptions.preset(convention, planarData);
    }

    private static LoadedTrajectory inMemory(Poses p) {
        // the format is only a label inside core; the report says "memory" (see memoryInput)
        return new LoadedTrajectory(p.name(), p.isPlanar() ? TrajectoryFormat.CSV : TrajectoryFormat.TUM,
                "arrays given through the Java API", p.trajectory(), null, false);
    }

    private static EvaluationReport.InputInfo memoryInput(EvaluationReport.InputInfo i) {
        return new EvaluationReport.InputInfo(i.path(), MEMORY_FORMAT, i.formatReason(), i.poses(), null);
    }
}
