package org.trajeval.pipeline;

import org.trajeval.core.report.EvaluationReport;

/** Scores one run: reads its two trajectories and evaluates the estimate against the reference. */
public interface RunScorer {
    /**
     * @return the evaluation report of the run
     * @throws org.trajeval.core.InputException when a file cannot be read or the pair cannot be scored
     */
    EvaluationReport score(RunJob job);

    /**
     * Scores keeping the per-pose series, for the run's figures; a scorer that keeps none returns
     * its report with null series (the run is then reported with a {@code plot_failed} warning).
     *
     * @throws org.trajeval.core.InputException as {@link #score}
     */
    default org.trajeval.core.report.SavedEvaluation scoreWithSeries(RunJob job) {
        return new org.trajeval.core.report.SavedEvaluation(score(job), null);
    }

    /**
     * Reads the run's two files once, parsing and hashing each in one pass, for the run's content
     * hash and {@link #score(RunJob, RunInputs)}.
     *
     * @return the inputs, or null when this scorer does not read ahead (the files are then hashed
     *     apart from scoring)
     * @throws org.trajeval.core.InputException as {@link #score}
     */
    default RunInputs read(RunJob job) {
        return null;
    }

    /** As {@link #score(RunJob)}, on the inputs {@link #read} returned (not null). */
    default EvaluationReport score(RunJob job, RunInputs inputs) {
        return score(job);
    }

    /** As {@link #scoreWithSeries(RunJob)}, on the inputs {@link #read} returned (not null). */
    default org.trajeval.core.report.SavedEvaluation scoreWithSeries(RunJob job, RunInputs inputs) {
        return scoreWithSeries(job);
    }
}
