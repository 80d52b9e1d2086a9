package org.trajeval.core.eval;

import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.report.EvaluationReport;

/** Scores an estimate against a reference: association, alignment, ATE, RPE, drift. */
public final class Evaluator {
    private Evaluator() {
    }

    /**
     * Evaluates one pair and returns the report (the same object {@code trajeval eval --json}
     * prints).
     *
     * @throws org.trajeval.core.InputException when the pair cannot be scored (no overlap, too
     *     few poses, degenerate alignment)
     */
    public static EvaluationReport evaluate(LoadedTrajectory reference, LoadedTrajectory estimate,
            EvaluationOptions options) {
        throw new UnsupportedOperationException("engine not yet implemented");
    }
}
