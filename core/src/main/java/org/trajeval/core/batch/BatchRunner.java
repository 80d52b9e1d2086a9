package org.trajeval.core.batch;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import org.trajeval.core.InputException;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.eval.Parallelism;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryFiles;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.FileRole;
import org.trajeval.core.options.FormatApplicability;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;

/**
 * Scores many pairs in one process: each pair read, evaluated ({@link Evaluator#evaluate}) and its
 * report written (atomically: temporary file, fsync, rename; by a {@link ReportWriter} while the
 * next pair is scored) into the report folder as {@code NAME.json}, then forgotten but for its
 * summary row; finally {@link BatchSummary#FILE}.
 * Pairs are scored one per thread, several at once; a pair that cannot be scored is a failed row
 * with its reason and the batch goes on.
 */
public final class BatchRunner {
    private BatchRunner() {
    }

    /**
     * Scores one pair; bad input (and, caught here as at a top-level handler, any other
     * exception) becomes a failed row.
     *
     * @param base the job's settings, which the row's own settings refine
     * @param table the table's name, for refusals of the row's settings ({@code pairs.csv:7: ...})
     * @param reportDir where the report is written as {@code NAME.json}
     */
    public static BatchResult score(BatchPair pair, SettingValues base, String table, ReadOptions limits,
            PathResolver paths, Path reportDir) {
        BatchResult[] row = new BatchResult[1];
        score(pair, base, table, limits, paths, reportDir, null, r -> row[0] = r);
        return row[0];
    }

    /**
     * Scores one pair and hands its report to {@code writer} (written on the calling thread when
     * null); {@code finished} receives the row once the report is written or the pair failed.
     */
    private static void score(BatchPair pair, SettingValues base, String table, ReadOptions limits,
            PathResolver paths, Path reportDir, ReportWriter writer, Consumer<BatchResult> finished) {
        EvaluationReport report;
        String json;
        try {
            report = evaluate(pair, base, table + ":" + pair.line(), limits, paths);
            json = ReportJson.toJson(report) + "\n";
        } catch (RuntimeException e) { // bad input, or a bug: the row says which, the batch goes on
            finished.accept(failed(pair, e));
            return;
        }
        if (writer == null) {
            finished.accept(ReportWriter.writeNow(pair, report, json, reportDir));
        } else {
            writer.write(pair, report, json, reportDir, finished);
        }
    }

    /**
     * Reads and scores one pair as {@code trajeval eval} does (the row's settings refine the job's;
     * settings checked against the formats read), without writing anything: the step a Spark task
     * runs per row.
     *
     * @param settingsSource how refusals of the row's settings name it ({@code pairs.csv:7})
     * @throws InputException when the pair cannot be scored
     */
    public static EvaluationReport evaluate(BatchPair pair, SettingValues base, String settingsSource,
            ReadOptions limits, PathResolver paths) {
        return evaluate(pair, base, settingsSource, limits, paths, TrajectoryFiles.LOCAL);
    }

    /**
     * As {@link #evaluate(BatchPair, SettingValues, String, ReadOptions, PathResolver)}, the files
     * read by {@code files} (e.g. through Hadoop's FileSystem API for {@code hdfs:} pairs).
     */
    public static EvaluationReport evaluate(BatchPair pair, SettingValues base, String settingsSource,
            ReadOptions limits, PathResolver paths, TrajectoryFiles files) {
        SettingValues s = base.with(pair.settings(), settingsSource);
        LoadedTrajectory ref = files.read(pair.reference(),
                SettingsResolver.readOptions(s, FileRole.REFERENCE, limits, paths));
        LoadedTrajectory est = files.read(pair.estimate(),
                SettingsResolver.readOptions(s, FileRole.ESTIMATE, limits, paths));
        FormatApplicability.check(s, ref, pair.reference(), est, pair.estimate());
        EvaluationOptions options = SettingsResolver.evaluationOptions(s,
                DataKind.of(ref.trajectory(), est.trajectory()));
        return Evaluator.evaluate(ref, est, options);
    }

    /**
     * @return the failed row of a pair whose scoring threw {@code e}: bad input gives its problem as
     *     the reason, anything else {@link BatchResult#INTERNAL_ERROR} (caught as at a top-level handler)
     */
    public static BatchResult failed(BatchPair pair, RuntimeException e) {
        if (e instanceof java.nio.file.InvalidPathException) {
            return BatchResult.failed(pair, "unreadable", "not a file path: " + e.getMessage());
        }
        if (e instanceof InputException ie) {
            return BatchResult.failed(pair, ie.problem().name().toLowerCase(Locale.ROOT), ie.getMessage());
        }
        return BatchResult.failed(pair, BatchResult.INTERNAL_ERROR, e.getClass().getName()
                + (e.getMessage() == null ? "" : ": " + e.getMessage()));
    }

    /**
     * Scores every pair, {@code parallelism.threads()} pairs at a time (each pair on one thread),
     * the reports written by a {@link ReportWriter} while the next pairs are scored; then writes
     * the summary.
     *
     * @param done called with each row once its report is written (or it failed), from the worker
     *     threads or the report writer's
     * @return the rows in table order
     */
    public static List<BatchResult> run(List<BatchPair> pairs, SettingValues base, String table, ReadOptions limits,
            PathResolver paths, Path reportDir, Parallelism parallelism, Consumer<BatchResult> done) {
        BatchResult[] out = new BatchResult[pairs.size()];
        try (ReportWriter writer = new ReportWriter()) {
            parallelism.forEach(out.length, k -> score(pairs.get(k), base, table, limits, paths, reportDir, writer,
                    r -> {
                        out[k] = r;
                        done.accept(r);
                    }));
        }
        List<BatchResult> rows = Arrays.asList(out);
        ReportJson.writeAtomically(reportDir.resolve(BatchSummary.FILE), BatchSummary.csv(rows));
        return rows;
    }
}
