package org.trajeval.spark;

import java.io.Serializable;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import org.apache.spark.api.java.function.MapPartitionsFunction;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.RowFactory;
import org.trajeval.core.InputException;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.FileRole;
import org.trajeval.core.options.FormatApplicability;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.SettingText;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.protocol.RunMetric;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;

/**
 * Scores the pairs of one partition, one output row per input row: the input's values, then the
 * {@link ResultSchema#RESULT} columns. The same steps as {@code trajeval eval}: both files read
 * with the settings' read options, the settings checked against the formats read, the
 * convention's preset resolved for the data kind, then the evaluation (on the task's thread).
 * A pair that cannot be scored is a {@code failed} row, never a failed task.
 */
final class PairScorer implements MapPartitionsFunction<Row, Row>, Serializable {
    private static final long serialVersionUID = 1L;

    private final PairColumns columns;
    /** The job's settings as (key, text, where) triples: SettingText is not Serializable. */
    private final String[][] jobSettings;
    private final PairFiles files;

    PairScorer(PairColumns columns, List<SettingText> jobSettings, PairFiles files) {
        this.columns = columns;
        this.jobSettings = jobSettings.stream().map(t -> new String[] {t.key(), t.text(), t.where()})
                .toArray(String[][]::new);
        this.files = files;
    }

    @Override
    public Iterator<Row> call(Iterator<Row> rows) {
        // the job's settings were checked on the driver; checked once more here per partition
        List<SettingText> given = new ArrayList<>();
        for (String[] t : jobSettings) {
            given.add(new SettingText(t[0], t[1], t[2]));
        }
        SettingValues job = SettingValues.of(given, TrajevalSpark.SETTINGS_SOURCE);
        return new Iterator<>() {
            @Override
            public boolean hasNext() {
                return rows.hasNext();
            }

            @Override
            public Row next() {
                return score(rows.next(), job);
            }
        };
    }

    private Row score(Row in, SettingValues job) {
        Object[] out = new Object[in.size() + ResultSchema.RESULT.size()];
        for (int i = 0; i < in.size(); i++) {
            out[i] = in.get(i);
        }
        int at = in.size();
        out[at] = ResultSchema.VERSION;
        try {
            EvaluationReport r = evaluate(in, job);
            out[at + 1] = ResultSchema.OK;
            fill(out, at + 4, r);
        } catch (InputException e) {
            out[at + 1] = ResultSchema.FAILED;
            out[at + 2] = e.problem().name().toLowerCase(Locale.ROOT);
            out[at + 3] = e.getMessage();
        } catch (java.io.UncheckedIOException e) {
            // a file that cannot be read (as trajeval eval: bad input)
            out[at + 1] = ResultSchema.FAILED;
            out[at + 2] = "unreadable";
            out[at + 3] = e.getMessage();
        } catch (RuntimeException e) {
            // the per-pair boundary: a bug scoring one pair fails that row, not the job
            out[at + 1] = ResultSchema.FAILED;
            out[at + 2] = ResultSchema.INTERNAL;
            out[at + 3] = "internal error: " + e;
        }
        return RowFactory.create(out);
    }

    private EvaluationReport evaluate(Row in, SettingValues job) {
        String refText = columns.ref(in);
        String estText = columns.est(in);
        List<SettingText> own = columns.settings(in);
        SettingValues s = own.isEmpty() ? job : job.with(own, "pair " + estText);
        Path ref = files.resolve(refText, PairColumns.REF);
        Path est = files.resolve(estText, PairColumns.EST);
        LoadedTrajectory r = TrajectoryReader.read(ref, SettingsResolver.readOptions(s, FileRole.REFERENCE,
                ReadOptions.defaults(), PathResolver.asWritten()));
        LoadedTrajectory e = TrajectoryReader.read(est, SettingsResolver.readOptions(s, FileRole.ESTIMATE,
                ReadOptions.defaults(), PathResolver.asWritten()));
        FormatApplicability.check(s, r, ref.toString(), e, est.toString());
        EvaluationOptions o = SettingsResolver.evaluationOptions(s, DataKind.of(r.trajectory(), e.trajectory()));
        return Evaluator.evaluate(r, e, o);
    }

    /** Writes the statistic columns from {@code r}, starting at {@code at} (the first RunMetric). */
    private static void fill(Object[] out, int at, EvaluationReport r) {
        int i = at;
        for (RunMetric m : RunMetric.values()) {
            double v = m.of(r);
            out[i++] = Double.isNaN(v) ? null : v;
        }
        out[i++] = r.ate() == null ? null : r.ate().transM().max();
        out[i++] = r.coverage() == null ? null : r.coverage().fraction();
        out[i++] = r.association() == null ? null : r.association().matched();
        out[i++] = r.association() == null ? null : r.association().dropped();
        out[i++] = r.association() == null ? null : r.association().droppedReference();
        out[i++] = r.inputs().reference().poses();
        out[i++] = r.inputs().estimate().poses();
        out[i++] = r.alignment() == null ? null : r.alignment().model();
        out[i++] = String.join(";", r.warnings().stream().map(EvaluationReport.Warning::code).toList());
        out[i] = ReportJson.toJson(r);
    }
}
