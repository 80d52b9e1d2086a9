package org.trajeval.pipeline;

import java.nio.file.Path;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.SavedEvaluation;
import org.trajeval.pipeline.bundle.ContentHash;

/**
 * Turns one {@link RunJob} into a report: read (each file parsed and hashed in one pass), fingerprint,
 * skip if already reported, score ({@link #score}), file the report ({@link #file}). Shared by the
 * directory and the Kafka mode. Thread-safe.
 */
public final class RunProcessor {
    private final RunScorer scorer;
    private final ReportStore store;

    /**
     * @param scorer reads and scores the trajectories
     * @param store files reports and keeps the ledger
     */
    public RunProcessor(RunScorer scorer, ReportStore store) {
        this.scorer = scorer;
        this.store = store;
    }

    /** @return the store the reports go to */
    public ReportStore store() {
        return store;
    }

    /**
     * Processes a run: {@link #file} of {@link #score}.
     *
     * @throws StageException when the run cannot be scored (with stage and reason)
     * @throws EnvironmentException when the report or the ledger cannot be written (disk full, read-only
     *     folder): the run is not at fault and must be retried
     */
    public RunResult process(RunJob job) {
        return file(score(job));
    }

    /**
     * A run read, fingerprinted and scored, its report not yet filed: either {@code duplicate} (its
     * content was reported before: nothing to file) or the evaluation with the draft of its figures.
     */
    public record Scored(RunJob job, ContentHash hash, EvaluationReport evaluation, Path draft, RunResult duplicate) {
    }

    /**
     * The computing half of {@link #process}: reads (each file parsed and hashed in one pass),
     * fingerprints, looks the content up in the ledger, scores and draws the figures asked for.
     * Writes nothing durable: a caller may hand the result to another thread for {@link #file}.
     *
     * @throws StageException when the run cannot be scored (with stage and reason)
     */
    public Scored score(RunJob job) {
        ContentHash hash;
        RunInputs inputs;
        try {
            // each file read once: parsed and hashed in one pass (a scorer that does not read ahead: hashed here)
            inputs = scorer.read(job);
            hash = inputs == null ? ContentHash.of(job) : ContentHash.of(job, inputs.reference().sha256(),
                    inputs.estimate().sha256());
        } catch (RuntimeException e) {
            throw new StageException(RunFailure.of(Stage.SCORE, e), e);
        }
        String runId = job.metadata().runId();
        if (store.probablyReported(runId, hash)) {
            var earlier = store.find(runId, hash);
            if (earlier.isPresent()) {
                int v = earlier.get().version();
                return new Scored(job, hash, null, null, new RunResult(Outcome.DUPLICATE, runId, v,
                        store.reportFile(runId, v), null, earlier.get().source()));
            }
        }
        EvaluationReport evaluation;
        SavedEvaluation saved = null;
        try {
            if (job.plot()) {
                saved = inputs == null ? scorer.scoreWithSeries(job) : scorer.scoreWithSeries(job, inputs);
                evaluation = saved.report();
            } else {
                evaluation = inputs == null ? scorer.score(job) : scorer.score(job, inputs);
            }
        } catch (RuntimeException e) {
            throw new StageException(RunFailure.of(Stage.SCORE, e), e);
        }
        Path draft = null;
        if (saved != null) {
            try {
                draft = RunPlots.draft(saved, store.reportsDir(), runId);
            } catch (RuntimeException | LinkageError | java.awt.AWTError e) {
                // drawing never costs the run its report (a headless JVM without fonts throws errors)
                evaluation = evaluation.withWarning(plotFailed(e));
            }
        }
        return new Scored(job, hash, evaluation, draft, null);
    }

    /**
     * The durable half of {@link #process}: files the scored run's report (written and fsync'd, then
     * its ledger line fsync'd: {@link ReportStore#commit}); a duplicate is returned as it is.
     *
     * @throws StageException when the report cannot be made (with stage and reason)
     * @throws EnvironmentException when the report or the ledger cannot be written (disk full, read-only
     *     folder): the run is not at fault and must be retried
     */
    public RunResult file(Scored scored) {
        if (scored.duplicate() != null) {
            return scored.duplicate();
        }
        try {
            return store.commit(scored.job(), scored.hash(), scored.evaluation(), scored.draft());
        } catch (java.io.UncheckedIOException e) {
            throw EnvironmentException.of(e);
        } catch (EnvironmentException e) {
            throw e;
        } catch (RuntimeException e) {
            throw new StageException(RunFailure.of(Stage.REPORT, e), e);
        } finally {
            RunPlots.discard(scored.draft()); // moved into place, or not wanted (a duplicate, a failed commit)
        }
    }

    /** @return the report's warning for figures that could not be drawn or moved into place */
    static EvaluationReport.Warning plotFailed(Throwable e) {
        String why = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        return new EvaluationReport.Warning("plot_failed", "the run's figures (plot: true) could not be written: "
                + org.trajeval.core.InputText.escape(why) + "; the numbers are unaffected");
    }
}
