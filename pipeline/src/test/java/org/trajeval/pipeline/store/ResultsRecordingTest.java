package org.trajeval.pipeline.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.pipeline.ConfigLoader;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.PipelineCommand;
import org.trajeval.pipeline.PipelineConfig;
import org.trajeval.pipeline.ReportStore;
import org.trajeval.pipeline.StandInScorer;
import org.trajeval.pipeline.ledger.Ledger;
import org.trajeval.store.ReportImport;
import org.trajeval.store.ResultsStore;
import org.trajeval.store.RunRecord;
import org.trajeval.store.Selection;
import org.trajeval.store.StoreLocation;
import picocli.CommandLine;

/** Every committed report reaches the results store once, also when the store was down. */
class ResultsRecordingTest {
    @TempDir
    Path root;

    private String drain(String... extra) {
        StringWriter out = new StringWriter();
        CommandLine cl = PipelineCommand.newCommandLine(c -> new StandInScorer(), Map.of());
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(out));
        String[] args = new String[3 + extra.length + 1];
        args[0] = "watch";
        args[1] = "--root";
        args[2] = root.toString();
        System.arraycopy(extra, 0, args, 3, extra.length);
        args[args.length - 1] = "--drain";
        assertEquals(0, cl.execute(args), out.toString());
        return out.toString();
    }

    private void drop(String name, long seed) {
        Fixtures.pair(root.resolve("incoming"), name, 30, seed);
        Fixtures.marker(root.resolve("incoming"), name);
    }

    private static List<RunRecord> stored(StoreLocation loc) {
        try (ResultsStore s = ResultsStore.open(loc, Clock.systemUTC())) {
            return s.select(Selection.all());
        }
    }

    @Test
    void everyReportIsRecordedOnceBesideTheReports() {
        for (int i = 0; i < 4; i++) {
            drop("r" + i, i);
        }
        drain();
        drop("r0", 0); // the same run again: a duplicate, no second report, no second row
        assertTrue(drain().contains("reported=0 duplicates=1"));
        List<RunRecord> rows = stored(StoreLocation.sqlite(root.resolve("trajeval.db")));
        assertEquals(4, rows.size());
        assertEquals(List.of("r0", "r1", "r2", "r3"), rows.stream().map(RunRecord::runId).sorted().toList());
        assertTrue(rows.stream().allMatch(r -> r.metrics().containsKey("ate_trans_rmse_m")));
    }

    @Test
    void aStoreThatIsDownLosesNothingAndTheBacklogIsReplayedOnRecovery() throws Exception {
        Path storeDir = root.resolve("db-volume"); // missing: SQLite cannot create the file, the store is down
        String url = "jdbc:sqlite:" + storeDir.resolve("fleet.db");
        for (int i = 0; i < 3; i++) {
            drop("r" + i, i);
        }
        String out = drain("--set", "store.db=" + url);
        assertTrue(out.contains("reported=3"), out);
        assertEquals(3, Files.list(root.resolve("reports")).count(), "the reports are written whatever the store");

        // a running service whose store comes back: the replay task records the backlog
        PipelineConfig c = ConfigLoader.load(null, Map.of(), Map.of("root", root.toString(), "store.db", url,
                "store.retry_interval_s", "0.1"));
        AtomicLong lag = new AtomicLong();
        try (Ledger ledger = Ledger.open(root.resolve("ledger/ledger.log"))) {
            ResultsRecorder.Attached a = ResultsRecorder.attach(c, new ReportStore(root.resolve("reports"), ledger,
                    Clock.systemUTC()), lag, Map.of());
            try {
                Thread.sleep(300);
                assertEquals(-1, a.recorder().replay(), "still down");
                Files.createDirectories(storeDir);
                long deadline = System.nanoTime() + 20_000_000_000L;
                while (stored(StoreLocation.parse(url, Map.of())).size() < 3 && System.nanoTime() < deadline) {
                    Thread.sleep(100);
                }
            } finally {
                a.recorder().close();
            }
        }
        assertEquals(3, stored(StoreLocation.parse(url, Map.of())).size());
        assertEquals(0, lag.get());
    }

    @Test
    void twoInstancesAndAnImporterRecordingAtOnceLeaveEachRunOnce() throws Exception {
        for (int i = 0; i < 40; i++) {
            drop("r" + i, i);
        }
        String url = "jdbc:sqlite:" + root.resolve("shared.db");
        drain("--set", "store.db=none");
        PipelineConfig c = ConfigLoader.load(null, Map.of(), Map.of("root", root.toString(), "store.db", url));
        // two instances sharing the root replay the same ledger while an importer loads the reports folder
        try (Ledger l1 = Ledger.open(root.resolve("ledger/ledger.log"));
                Ledger l2 = Ledger.open(root.resolve("ledger/ledger.log"))) {
            ResultsRecorder.Attached a = ResultsRecorder.attach(c, new ReportStore(root.resolve("reports"), l1,
                    Clock.systemUTC()), new AtomicLong(), Map.of());
            ResultsRecorder.Attached b = ResultsRecorder.attach(c, new ReportStore(root.resolve("reports"), l2,
                    Clock.systemUTC()), new AtomicLong(), Map.of());
            try (ResultsStore importer = ResultsStore.open(StoreLocation.parse(url, Map.of()), Clock.systemUTC())) {
                ReportImport.run(importer, root.resolve("reports"), org.trajeval.store.Labels.none());
            }
            a.recorder().close();
            b.recorder().close();
        }
        List<RunRecord> rows = stored(StoreLocation.parse(url, Map.of()));
        assertEquals(40, rows.size());
        assertEquals(40, rows.stream().map(RunRecord::runId).distinct().count());
    }
}
