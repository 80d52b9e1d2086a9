package org.trajeval.cli;

import java.io.PrintWriter;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.SavedEvaluation;
import org.trajeval.figures.EvalPlotPage;

/** {@code eval --plot / --save-series}: one evaluation with its per-pose data, saved and drawn. */
final class EvalPlots {
    private EvalPlots() {
    }

    /** Evaluates keeping the per-pose series, writes what the options ask for, returns the report. */
    static EvaluationReport write(LoadedTrajectory ref, LoadedTrajectory est, EvaluationOptions options,
            double[] subTrajectoryLengthsM, PlotOptions plots, PrintWriter err) {
        SavedEvaluation saved = SavedEvaluation.score(ref, est, options, subTrajectoryLengthsM);
        if (plots.seriesDir != null) {
            saved.write(plots.seriesDir);
        }
        if (plots.plotDir != null) {
            EvalPlotPage.write(saved, plots.plane, plots.plotDir, plots.formats,
                    ProgressBar.counter(err, "figures"));
        }
        return saved.report();
    }
}
