package org.trajeval.pipeline;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.Version;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.stats.ErrorStatistics;
import org.trajeval.pipeline.bundle.ContentHash;

/**
 * A fast stand-in for the core engine in tests of the pipeline's own logic: reads {@code t,x,y,yaw} CSV (refusing a
 * non-number with the line, like the real reader), pairs poses by index and reports the RMSE of
 * the position differences. Only the pipeline's logic is under test with it, never a metric.
 */
public final class StandInScorer implements RunScorer {
    @Override
    public EvaluationReport score(RunJob job) {
        double[][] ref = read(job.reference());
        double[][] est = read(job.estimate());
        int n = Math.min(ref.length, est.length);
        double sse = 0;
        for (int i = 0; i < n; i++) {
            double dx = ref[i][1] - est[i][1];
            double dy = ref[i][2] - est[i][2];
            sse += dx * dx + dy * dy;
        }
        double rmse = Math.sqrt(sse / n);
        EvaluationReport.Stats stats = new EvaluationReport.Stats(rmse, null, null, null, null, null, sse, n);
        var inputs = new EvaluationReport.Inputs(
                new EvaluationReport.InputInfo(job.reference().getFileName().toString(), "csv", "stand-in", ref.length,
                        ContentHash.ofFile(job.reference())),
                new EvaluationReport.InputInfo(job.estimate().getFileName().toString(), "csv", "stand-in", est.length,
                        ContentHash.ofFile(job.estimate())));
        return new EvaluationReport(EvaluationReport.SCHEMA, EvaluationReport.SCHEMA_VERSION, Version.TOOL, "lesson",
                inputs, null, null, new EvaluationReport.Ate(stats, stats), null, null, null, null, null, null);
    }

    private static double[][] read(Path file) {
        List<String> lines;
        try {
            lines = Files.readAllLines(file);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        if (lines.size() < 3) {
            throw new InputException(file.getFileName().toString(), 0, null, InputProblem.TOO_FEW_POSES,
                    "at least 2 poses are needed", null);
        }
        double[][] out = new double[lines.size() - 1][4];
        for (int i = 1; i < lines.size(); i++) {
            String[] f = lines.get(i).split(",");
            if (f.length != 4) {
                throw new InputException(file.getFileName().toString(), i + 1, null, InputProblem.WRONG_FIELD_COUNT,
                        "a row must have 4 fields t,x,y,yaw", lines.get(i));
            }
            for (int j = 0; j < 4; j++) {
                try {
                    out[i - 1][j] = Double.parseDouble(f[j]);
                } catch (NumberFormatException e) {
                    throw new InputException(file.getFileName().toString(), i + 1, "t,x,y,yaw".split(",")[j],
                            InputProblem.NOT_A_NUMBER, "column must be a number", f[j]);
                }
            }
        }
        return out;
    }
}
