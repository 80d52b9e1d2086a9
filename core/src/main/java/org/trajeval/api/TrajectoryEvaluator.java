package org.trajeval.api;

import java.nio.file.Path;
import java.util.Map;
import java.util.Objects;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.FileRole;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.Setting;
import org.trajeval.core.options.SettingScope;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.options.SettingsTree;
import org.trajeval.core.report.EvaluationReport;

/**
 * The Java entry point of trajeval: scores an estimate against a reference (ground truth) and
 * returns the report {@code trajeval eval --json} prints, with the same numbers for the same
 * files and settings (ATE, RPE, optional drift; positions in m, angles in rad, times in s).
 *
 * <pre>{@code
 * TrajectoryEvaluator evaluator = TrajectoryEvaluator.of(Map.of("convention", "evo", "alignment", "se3"));
 * EvaluationReport report = evaluator.evaluate(Path.of("truth.txt"), Path.of("estimate.txt"));
 * double ateRmseM = report.ate().transM().rmse();
 * }</pre>
 *
 * <p>Settings are those of {@code trajeval eval}, a suite manifest's {@code metrics} and a
 * pipeline {@code run.yaml}: the same keys, values, defaults and checks (one table, README
 * "Evaluation settings"). As there, the convention's preset is resolved per pair from the data
 * (the lesson's se2 alignment for planar data, se3 for SE(3) data), and file formats are detected
 * from extension and content unless a format is set.
 *
 * <p>Thread safety: immutable; one instance may evaluate any number of pairs from any number of
 * threads at once. Each call works on the caller's thread only.
 *
 * <p>Errors: bad settings, bad input (unreadable or malformed file, no overlap in time, too few
 * poses, a degenerate alignment) throw {@link InputException}, whose fields name the source, line,
 * column or setting, and the problem; invalid arrays throw {@link IllegalArgumentException}.
 */
public final class TrajectoryEvaluator {
    /** The {@code inputs.*.format} of a trajectory given as arrays. */
    public static final String MEMORY_FORMAT = "memory";
    /** How refusals of the settings name their source. */
    public static final String SETTINGS_SOURCE = "settings";

    private final SettingValues settings;

    private TrajectoryEvaluator(SettingValues settings) {
        this.settings = settings;
    }

    /** @return an evaluator with every default (the lesson's convention), as {@code trajeval eval REF EST} */
    public static TrajectoryEvaluator withDefaults() {
        return new TrajectoryEvaluator(SettingValues.DEFAULTS);
    }

    /**
     * An evaluator with settings, checked now.
     *
     * @param settings keys and values as in a {@code run.yaml} (for example {@code convention: evo},
     *     {@code alignment: se3}, {@code rpe_delta: 10}, {@code rpe_unit: frames}); values are
     *     strings, numbers, booleans or lists of them; a nested map joins its keys with '_'
     *     ({@code rpe: {delta: 1, unit: s}}); path values ({@code ref_times}) are taken as written
     * @throws InputException (problem {@link InputProblem#INVALID_CONFIGURATION}) on an unknown key,
     *     a value outside its type or range, or settings that exclude each other, naming the key
     */
    public static TrajectoryEvaluator of(Map<String, ?> settings) {
        Objects.requireNonNull(settings, "settings");
        return new TrajectoryEvaluator(SettingValues.of(SettingsTree.flatten(settings, "", SETTINGS_SOURCE),
                SETTINGS_SOURCE));
    }

    /**
     * Reads and scores two trajectory files (CSV, TUM, KITTI, EuRoC).
     *
     * @throws InputException when a file cannot be read or the pair cannot be scored
     */
    public EvaluationReport evaluate(Path reference, Path estimate) {
        Objects.requireNonNull(reference, "reference");
        Objects.requireNonNull(estimate, "estimate");
        LoadedTrajectory ref = TrajectoryReader.read(reference, SettingsResolver.readOptions(settings,
                FileRole.REFERENCE, ReadOptions.defaults(), PathResolver.asWritten()));
        LoadedTrajectory est = TrajectoryReader.read(estimate, SettingsResolver.readOptions(settings,
                FileRole.ESTIMATE, ReadOptions.defaults(), PathResolver.asWritten()));
        return Evaluator.evaluate(ref, est, SettingsResolver.evaluationOptions(settings,
                DataKind.of(ref.trajectory(), est.trajectory())));
    }

    /**
     * Scores two trajectories given as arrays. The report's inputs have format
     * {@value #MEMORY_FORMAT}, the names given to {@link Poses}, and no SHA-256.
     *
     * @throws InputException when a setting of file reading was given (format, columns, sort, ...:
     *     arrays are not read), or when the pair cannot be scored (no overlap in time, too few
     *     poses, degenerate alignment)
     */
    public EvaluationReport evaluate(Poses reference, Poses estimate) {
        Objects.requireNonNull(reference, "reference");
        Objects.requireNonNull(estimate, "estimate");
        for (Setting s : Setting.values()) {
            if (s.scope() != SettingScope.EVALUATION && settings.has(s)) {
                throw new InputException(SETTINGS_SOURCE, 0, settings.where(s), InputProblem.INVALID_CONFIGURATION,
                        "'" + settings.where(s) + "' applies to reading files; trajectories given as arrays are not "
                                + "read (leave it out)", String.valueOf(settings.asText().get(s.key())));
            }
        }
        LoadedTrajectory ref = inMemory(reference);
        LoadedTrajectory est = inMemory(estimate);
        EvaluationReport r = Evaluator.evaluate(ref, est, SettingsResolver.evaluationOptions(settings,
                DataKind.of(ref.trajectory(), est.trajectory())));
        return r.withInputs(new EvaluationReport.Inputs(memoryInput(r.inputs().reference()),
                memoryInput(r.inputs().estimate())));
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
