package org.trajeval.pipeline;

import org.trajeval.core.report.EvaluationReport;

/** Scores one run: reads its two trajectories and evaluates the estimate against the reference. */
public interface RunScorer {
    /**
     * @return the evaluation report of the run
     * @throws org.trajeval.core.InputException when a file cannot be read or the pair cannot be scored
     */
    EvaluationReport score(RunJob job);
}
