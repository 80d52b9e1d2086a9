package org.trajeval.pipeline;

import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.FileRole;
import org.trajeval.core.options.FormatApplicability;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.SavedEvaluation;
import org.trajeval.pipeline.bundle.RunFields;

/**
 * The real scorer: {@link TrajectoryReader} for both files and {@link Evaluator}, with the run's
 * settings resolved by the core's {@link SettingsResolver} exactly as {@code trajeval eval} and
 * {@code trajeval suite} resolve theirs; file sizes limited by the pipeline's configuration.
 */
public final class CoreRunScorer implements RunScorer {
    private final long maxFileBytes;

    /** @param maxFileBytes largest accepted trajectory file (bytes) */
    public CoreRunScorer(long maxFileBytes) {
        this.maxFileBytes = maxFileBytes;
    }

    @Override
    public EvaluationReport score(RunJob job) {
        return score(job, read(job));
    }

    @Override
    public SavedEvaluation scoreWithSeries(RunJob job) {
        return scoreWithSeries(job, read(job));
    }

    @Override
    public RunInputs read(RunJob job) {
        LoadedTrajectory ref = named(TrajectoryReader.read(job.reference(),
                readOptions(job, FileRole.REFERENCE, maxFileBytes)), job);
        LoadedTrajectory est = named(TrajectoryReader.read(job.estimate(),
                readOptions(job, FileRole.ESTIMATE, maxFileBytes)), job);
        FormatApplicability.check(job.settings(), ref, ref.source(), est, est.source());
        return new RunInputs(ref, est);
    }

    @Override
    public EvaluationReport score(RunJob job, RunInputs in) {
        return Evaluator.evaluate(in.reference(), in.estimate(), SettingsResolver.evaluationOptions(job.settings(),
                DataKind.of(in.reference().trajectory(), in.estimate().trajectory())));
    }

    @Override
    public SavedEvaluation scoreWithSeries(RunJob job, RunInputs in) {
        return SavedEvaluation.score(in.reference(), in.estimate(), SettingsResolver.evaluationOptions(job.settings(),
                DataKind.of(in.reference().trajectory(), in.estimate().trajectory())),
                SettingsResolver.subTrajectoryLengthsM(job.settings()));
    }

    /**
     * @return the read options of one file of the run: its settings, path settings resolved inside
     *     the bundle folder (a run without one cannot name files)
     * @throws InputException when a path setting leaves the bundle or has no bundle
     */
    public static ReadOptions readOptions(RunJob job, FileRole role, long maxFileBytes) {
        String source = job.settings().source() != null ? job.settings().source() : job.source();
        PathResolver paths = (text, where) -> {
            if (job.folder() == null) {
                throw new InputException(source, 0, where, InputProblem.INVALID_CONFIGURATION,
                        "'" + where + "' names a file, which only a bundle can carry", text);
            }
            return RunFields.fileInBundle(job.folder(), text, source, where, maxFileBytes);
        };
        return SettingsResolver.readOptions(job.settings(), role,
                ReadOptions.defaults().withLimits(maxFileBytes, ReadOptions.DEFAULT_MAX_POSES), paths);
    }

    /**
     * The report names an input by bundle and file ({@code run1.pair/run1.gt.csv}), not by its
     * path under processing/, which no longer exists once the bundle has moved on.
     */
    private static LoadedTrajectory named(LoadedTrajectory t, RunJob job) {
        String name = job.source() + "/" + java.nio.file.Paths.get(t.source()).getFileName();
        return new LoadedTrajectory(name, t.format(), t.formatReason(), t.trajectory(), t.sha256(),
                t.indexTimestamps());
    }
}
