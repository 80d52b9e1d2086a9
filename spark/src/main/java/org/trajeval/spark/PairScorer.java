package org.trajeval.spark;

import java.io.Serializable;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;
import org.apache.spark.api.java.function.MapPartitionsFunction;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.RowFactory;
import org.trajeval.core.batch.BatchPair;
import org.trajeval.core.batch.BatchResult;
import org.trajeval.core.batch.BatchRunner;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.SettingText;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.protocol.RunMetric;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;

/**
 * Scores the pairs of one partition, one output row per input row: the input's values, then the
 * {@link ResultSchema#RESULT} columns. Each row is core's batch step ({@link BatchRunner#evaluate},
 * the steps of {@code trajeval eval} and {@code eval --batch}) on the task's thread; a pair that
 * cannot be scored is a {@code failed} row ({@link BatchRunner#failed}), never a failed task.
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
        BatchPair pair = null;
        try {
            String est = columns.est(in);
            pair = new BatchPair(0, null, PairFiles.check(columns.ref(in), PairColumns.REF),
                    PairFiles.check(est, PairColumns.EST), columns.settings(in), Map.of());
            EvaluationReport r = BatchRunner.evaluate(pair, job, "pair " + est, ReadOptions.defaults(),
                    PathResolver.asWritten(), files);
            BatchResult row = BatchResult.scored(pair, r, null);
            out[at + 1] = row.status();
            fill(out, at + 4, row, r);
        } catch (RuntimeException e) {
            // the per-pair boundary (core's batch rule): bad input or a bug fails this row, not the job
            BatchResult row = BatchRunner.failed(pair != null ? pair : new BatchPair(0, null, "", "", List.of(),
                    Map.of()), e);
            out[at + 1] = row.status();
            out[at + 2] = row.failureReason();
            out[at + 3] = row.failureDetail();
        }
        return RowFactory.create(out);
    }

    /** Writes the statistic columns of a scored row, starting at {@code at} (the first RunMetric). */
    private static void fill(Object[] out, int at, BatchResult row, EvaluationReport r) {
        int i = at;
        for (RunMetric m : RunMetric.values()) {
            double v = row.metric(m);
            out[i++] = Double.isNaN(v) ? null : v;
        }
        out[i++] = r.ate() == null ? null : r.ate().transM().max();
        out[i++] = Double.isNaN(row.coverage()) ? null : row.coverage();
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
