package org.trajeval.pipeline.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.time.Clock;
import java.util.Comparator;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;
import org.trajeval.pipeline.CoreRunScorer;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.PipelineCommand;
import org.trajeval.pipeline.PipelineReport;
import org.trajeval.pipeline.RunJob;
import org.trajeval.pipeline.RunMetadata;
import org.trajeval.store.Labels;
import org.trajeval.store.ReportRecords;
import org.trajeval.store.ResultsStore;
import org.trajeval.store.RunRecord;
import org.trajeval.store.Selection;
import org.trajeval.store.StoreLocation;

/**
 * The recorder takes the report in hand, batched, instead of reading each report file back: the
 * rows are the ones the report files give (the general path: {@code ReportRecords.fromPipeline} on
 * the file's text), and a report whose ledger line is durable but whose row is not is recorded
 * exactly once when the service starts again.
 */
class ReportInHandTest {
    private static final String FIELDS = "site: lab\nsoftware_version: \"2.1\"\ntags: {shift: night, build: a7}\n"
            + "domain: sim\nsimulator: gazebo\nscenario: c1\nfactors: {obstacle_density: 0.4, speed: 1.25}\n"
            + "environment: warehouse\nmodality: [lidar, wheel]\nground_truth: simulator\n"
            + "resources: {wall_time_s: 12.5, peak_memory_mib: 640, device: cpu}\n";

    @TempDir
    Path root;

    private String drain(String... extra) {
        StringWriter out = new StringWriter();
        picocli.CommandLine cl = PipelineCommand.newCommandLine(c -> new CoreRunScorer(1 << 20), Map.of());
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(out));
        String[] args = new String[4 + extra.length];
        args[0] = "watch";
        args[1] = "--root";
        args[2] = root.toString();
        System.arraycopy(extra, 0, args, 3, extra.length);
        args[args.length - 1] = "--drain";
        assertEquals(0, cl.execute(args), out.toString());
        return out.toString();
    }

    private void drop(String name, long seed) {
        Path b = Fixtures.folderBundle(root.resolve("incoming"), name, name, 60, seed);
        Fixtures.write(b.resolve("run.yaml"), Fixtures.manifest(name, "bot-" + (seed % 3), "gt.csv", "est.csv")
                + FIELDS);
        Fixtures.marker(root.resolve("incoming"), name);
    }

    private static List<RunRecord> stored(StoreLocation loc) {
        try (ResultsStore s = ResultsStore.open(loc, Clock.systemUTC())) {
            return s.select(Selection.all()).stream().sorted(Comparator.comparing(RunRecord::resultSha256)).toList();
        }
    }

    /**
     * The rows the report files give (the general path): a service started on this root with a fresh
     * store records every report of the ledger from its file.
     */
    private List<RunRecord> fromFiles() {
        String url = "jdbc:sqlite:" + root.resolve("from-files-" + System.nanoTime() + ".db");
        assertTrue(drain("--set", "store.db=" + url).contains("reported=0"));
        return stored(StoreLocation.parse(url, Map.of()));
    }

    @Test
    void aReportInHandGivesTheRowItsFileGives() throws Exception {
        Path dir = root.resolve("pair");
        Fixtures.writeTrajectory(dir.resolve("gt.csv"), 120, 0.0, 3);
        Fixtures.writeTrajectory(dir.resolve("est.csv"), 120, 0.05, 4);
        EvaluationReport evaluation = new CoreRunScorer(1 << 20).score(new RunJob(RunMetadata.ofName("r"),
                dir.resolve("gt.csv"), dir.resolve("est.csv"), SettingValues.DEFAULTS, "test"));
        PipelineReport report = new PipelineReport(PipelineReport.SCHEMA, PipelineReport.SCHEMA_VERSION, "0.1.0",
                "r7", "bot-2", "loop", "vio", 42L, "lab", "2.1", Map.of("shift", "night", "build", "a7"), "sim",
                "gazebo", "c1", Map.of("obstacle_density", 0.4, "speed", 1.0 / 3), "warehouse", "lidar+wheel",
                "simulator", new PipelineReport.Resources(12.5, 640, 3.25, "cpu"), 3, "a".repeat(64),
                "b".repeat(64), "c".repeat(64), "r7", "2026-11-25T18:51:02.123456Z", evaluation);
        String json = ReportJson.toJson(report);
        for (Labels labels : List.of(Labels.none(), Labels.parse(List.of("robot=override", "campaign=k3")))) {
            RunRecord fromFile = ReportRecords.fromPipeline(json, "reports/r7.v3.json", labels);
            RunRecord inHand = ReportRecords.fromPipeline(ResultsRecorder.fields(report), "reports/r7.v3.json", labels);
            assertEquals(fromFile, inHand);
        }
        assertTrue(ReportRecords.fromPipeline(json, "f", Labels.none()).metrics().size() >= 4, "real metrics compared");
    }

    @Test
    void liveRowsEqualTheRowsTheReportFilesGive() throws Exception {
        for (int i = 0; i < 12; i++) {
            drop("r" + i, i);
        }
        assertTrue(drain().contains("reported=12"));
        List<RunRecord> live = stored(StoreLocation.sqlite(root.resolve("trajeval.db")));
        assertEquals(12, live.size());
        assertEquals(fromFiles(), live);
        assertEquals("lab", live.get(0).site());
        for (String db : List.of("trajeval.db", "replayed.db")) {
            if (db.equals("replayed.db")) {
                assertTrue(drain("--set", "store.db=jdbc:sqlite:" + root.resolve(db)).contains("reported=0"));
            }
            try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + root.resolve(db));
                    Statement s = c.createStatement();
                    ResultSet rs = s.executeQuery("SELECT COUNT(*), MIN(factors), MAX(factors), MIN(modality), "
                            + "SUM(wall_time_s) FROM runs")) {
                assertTrue(rs.next());
                assertEquals(12, rs.getInt(1), db);
                assertEquals("obstacle_density=0.4;speed=1.25", rs.getString(2), db);
                assertEquals("obstacle_density=0.4;speed=1.25", rs.getString(3), db);
                assertEquals("lidar+wheel", rs.getString(4), db);
                assertEquals(12 * 12.5, rs.getDouble(5), 0.0, db);
            }
        }
    }

    @Test
    void aRunWhoseLedgerLineIsDurableButWhoseRowIsNotIsRecordedOnceAtTheNextStart() throws Exception {
        // store.db=none leaves what a crash after the ledger line, before the batched recording, leaves:
        // the report and its ledger line, no row
        for (int i = 0; i < 6; i++) {
            drop("r" + i, i);
        }
        assertTrue(drain("--set", "store.db=none").contains("reported=6"));
        StoreLocation db = StoreLocation.sqlite(root.resolve("trajeval.db"));
        assertEquals(0, stored(db).size());
        // the next start records them from the ledger, and records new runs live beside them, each once
        for (int i = 6; i < 9; i++) {
            drop("r" + i, i);
        }
        assertTrue(drain().contains("reported=3"));
        assertEquals(9, stored(db).size());
        assertEquals(fromFiles(), stored(db));
        drop("r0", 0); // the same run again: a duplicate, no second row
        assertTrue(drain().contains("duplicates=1"));
        assertEquals(9, stored(db).size());
        // the trend aggregates counted each run once
        try (Connection c = DriverManager.getConnection(db.jdbcUrl()); Statement s = c.createStatement();
                ResultSet rs = s.executeQuery("SELECT SUM(n) FROM trend_cells WHERE metric = 'ate_trans_rmse_m' "
                        + "AND slice = 'robot'")) {
            assertTrue(rs.next());
            assertEquals(9, rs.getLong(1));
        }
        assertNotNull(stored(db).get(0).metrics().get("ate_trans_rmse_m"));
    }
}
