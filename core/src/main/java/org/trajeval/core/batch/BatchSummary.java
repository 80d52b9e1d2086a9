package org.trajeval.core.batch;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.trajeval.core.protocol.RunMetric;
import org.trajeval.core.report.CsvText;

/**
 * The summary table of a batch ({@code summary.csv}): one row per pair in table order, with the
 * column names of a suite's {@code runs.csv} where they mean the same thing: the pass-through
 * columns first (so a table with {@code method,sequence,seed,split} columns gives them under
 * those names), then {@code reference}, {@code estimate}, {@code status}, {@code failure_reason},
 * {@code failure_detail}, {@code coverage}, one column per {@link RunMetric} key
 * ({@code ate_trans_rmse_m}, ..., {@code drift_trans_pct}) and {@code report} (the report's file
 * name). Numbers as {@link Double#toString}; absent values empty.
 */
public final class BatchSummary {
    /** File name of the summary in the report folder. */
    public static final String FILE = "summary.csv";

    private BatchSummary() {
    }

    /** @return the header of the summary of these rows */
    public static List<String> header(List<BatchResult> rows) {
        List<String> h = new ArrayList<>(passThroughColumns(rows));
        h.addAll(List.of("reference", "estimate", "status", "failure_reason", "failure_detail", "coverage"));
        for (RunMetric m : RunMetric.values()) {
            h.add(m.key());
        }
        h.add("report");
        return h;
    }

    /** @return the summary as CSV text */
    public static String csv(List<BatchResult> rows) {
        Set<String> pass = passThroughColumns(rows);
        StringBuilder sb = new StringBuilder();
        CsvText.row(sb, header(rows));
        for (BatchResult r : rows) {
            List<String> f = new ArrayList<>();
            for (String c : pass) {
                f.add(r.pair().passThrough().getOrDefault(c, ""));
            }
            f.add(r.pair().reference());
            f.add(r.pair().estimate());
            f.add(r.status());
            f.add(r.failureReason());
            f.add(r.failureDetail());
            f.add(CsvText.number(r.coverage()));
            for (RunMetric m : RunMetric.values()) {
                f.add(CsvText.number(r.metric(m)));
            }
            f.add(r.reportFile());
            CsvText.row(sb, f);
        }
        return sb.toString();
    }

    private static Set<String> passThroughColumns(List<BatchResult> rows) {
        Set<String> cols = new LinkedHashSet<>();
        for (BatchResult r : rows) {
            cols.addAll(r.pair().passThrough().keySet());
        }
        return cols;
    }
}
