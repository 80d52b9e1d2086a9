package org.trajeval.core.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.eval.Parallelism;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.protocol.RunMetric;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;

/** Many pairs in one process: a report per pair, failed rows with their reason, the summary table. */
class BatchRunnerTest {
    /** Distances below this are equal (m); the sums of 101 poses are exact to far better. */
    static final double TOL_M = 1e-12;

    @TempDir
    Path dir;

    private void write(String name, String body) throws IOException {
        Files.writeString(dir.resolve(name), body, StandardCharsets.UTF_8);
    }

    /** A straight line at 1 m/s, 10 Hz for 10 s, shifted sideways by {@code dy} m. */
    private void line(String name, double dy) throws IOException {
        StringBuilder sb = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i <= 100; i++) {
            double t = i * 0.1;
            sb.append(t).append(',').append(t).append(',').append(dy).append(",0\n");
        }
        write(name, sb.toString());
    }

    private List<BatchResult> runTable(String table, int threads) throws IOException {
        write("pairs.csv", table);
        Path reports = dir.resolve("reports");
        List<BatchPair> pairs = PairsTable.read(dir.resolve("pairs.csv"), 1 << 20);
        ExecutorService pool = threads > 1 ? Executors.newFixedThreadPool(threads - 1) : null;
        try {
            return BatchRunner.run(pairs, SettingValues.DEFAULTS, "pairs.csv", ReadOptions.defaults(),
                    PathResolver.asWritten(), reports, threads > 1 ? new Parallelism(pool, threads)
                            : Parallelism.SEQUENTIAL, r -> { });
        } finally {
            if (pool != null) {
                pool.shutdownNow();
            }
        }
    }

    @Test
    void everyPairGetsItsReportAndBadPairsAreFailedRowsWithTheirReason() throws IOException {
        line("gt.csv", 0.0);
        line("left.csv", 0.1);
        line("right.csv", -0.25);
        write("nan.csv", "t,x,y,yaw\n0,0,0,0\n0.1,nan,0,0\n");
        List<BatchResult> rows = runTable("""
                sequence,method,ref,est,alignment
                line,left,gt.csv,left.csv,none
                line,missing,gt.csv,nowhere.csv,none
                line,nan,gt.csv,nan.csv,
                line,badsetting,gt.csv,left.csv,sideways
                line,right,gt.csv,right.csv,none
                """, 2);
        assertEquals(5, rows.size());
        // the estimate is 0.10 m (0.25 m) to the side everywhere and not aligned: ATE-RMSE by hand
        assertTrue(rows.get(0).ok());
        assertEquals(0.10, rows.get(0).metric(RunMetric.ATE_TRANS_RMSE_M), TOL_M);
        assertEquals(0.25, rows.get(4).metric(RunMetric.ATE_TRANS_RMSE_M), TOL_M);
        assertEquals("unreadable", rows.get(1).failureReason());
        assertEquals("not_finite", rows.get(2).failureReason());
        assertEquals("invalid_configuration", rows.get(3).failureReason());
        assertTrue(rows.get(3).failureDetail().startsWith("pairs.csv:5"), rows.get(3).failureDetail());
        assertTrue(Double.isNaN(rows.get(1).metric(RunMetric.ATE_TRANS_RMSE_M)));
        assertNull(rows.get(1).reportFile());
        // the report on disk is the pair's evaluation report
        EvaluationReport r = ReportJson.parseEvaluation(Files.readString(dir.resolve("reports/line-0002.json")));
        assertEquals(0.10, r.ate().transM().rmse(), TOL_M);
        assertEquals("line-0002.json", rows.get(0).reportFile());
        assertFalse(Files.exists(dir.resolve("reports/line-0003.json")));
    }

    @Test
    void summaryHasTheRunsCsvColumnNamesAndPassesOtherColumnsThrough() throws IOException {
        line("gt.csv", 0.0);
        line("left.csv", 0.1);
        runTable("""
                method,sequence,ref,est,alignment,note
                orb,"fr1, xyz",gt.csv,left.csv,none,"say ""hi""\"
                vo,fr2,gt.csv,missing.csv,none,
                """, 1);
        List<String> lines = Files.readAllLines(dir.resolve("reports/summary.csv"));
        assertEquals("method,sequence,note,reference,estimate,status,failure_reason,failure_detail,coverage,"
                + "ate_trans_rmse_m,ate_trans_mean_m,ate_rot_rmse_rad,rpe_trans_rmse_m,rpe_rot_rmse_rad,"
                + "drift_trans_pct,report", lines.get(0));
        assertTrue(lines.get(1).startsWith("orb,\"fr1, xyz\",\"say \"\"hi\"\"\"," + dir.resolve("gt.csv")), lines.get(1));
        assertTrue(lines.get(1).contains(",ok,,,1.0,0.1"), lines.get(1));
        assertTrue(lines.get(1).endsWith(",line-0002.json"), lines.get(1));
        assertTrue(lines.get(2).contains(",failed,unreadable,"), lines.get(2));
        assertEquals(3, lines.size());
    }

    @Test
    void rowsComeBackInTableOrderWhateverTheThreadCount() throws IOException {
        line("gt.csv", 0.0);
        StringBuilder table = new StringBuilder("name,ref,est,alignment\n");
        for (int k = 0; k < 12; k++) {
            line("e" + k + ".csv", 0.01 * k);
            table.append("p").append(k).append(",gt.csv,e").append(k).append(".csv,none\n");
        }
        List<BatchResult> one = runTable(table.toString(), 1);
        String summaryOne = Files.readString(dir.resolve("reports/summary.csv"));
        List<BatchResult> three = runTable(table.toString(), 3);
        for (int k = 0; k < 12; k++) {
            assertEquals("p" + k + ".json", three.get(k).reportFile());
            assertEquals(0.01 * k, three.get(k).metric(RunMetric.ATE_TRANS_RMSE_M), TOL_M);
            assertEquals(one.get(k).metric(RunMetric.RPE_TRANS_RMSE_M), three.get(k).metric(RunMetric.RPE_TRANS_RMSE_M));
        }
        assertEquals(summaryOne, Files.readString(dir.resolve("reports/summary.csv")));
    }

    @Test
    void aReportThatCannotBeWrittenIsAWriteFailedRowAndEveryOtherRowIsScored() throws IOException {
        line("gt.csv", 0.0);
        line("left.csv", 0.1);
        StringBuilder table = new StringBuilder("name,ref,est,alignment\n");
        for (int k = 0; k < 3 * ReportWriter.QUEUED; k++) {
            table.append("p").append(k).append(",gt.csv,left.csv,none\n");
        }
        // a folder that is not empty where report p5.json should go: the rename onto it fails
        Files.createDirectories(dir.resolve("reports/p5.json/keep"));
        List<BatchResult> rows = runTable(table.toString(), 2);
        assertEquals(3 * ReportWriter.QUEUED, rows.size());
        for (int k = 0; k < rows.size(); k++) {
            BatchResult r = rows.get(k);
            if (k == 5) {
                assertEquals(BatchResult.WRITE_FAILED, r.failureReason());
                assertTrue(r.failureDetail().startsWith("cannot write " + dir.resolve("reports/p5.json")),
                        r.failureDetail());
            } else {
                assertTrue(r.ok(), r.failureDetail());
                assertEquals("p" + k + ".json", r.reportFile());
                assertTrue(Files.isRegularFile(dir.resolve("reports/p" + k + ".json")));
            }
        }
        List<String> summary = Files.readAllLines(dir.resolve("reports/summary.csv"));
        assertTrue(summary.get(6).contains(",failed," + BatchResult.WRITE_FAILED + ","), summary.get(6));
    }
}
