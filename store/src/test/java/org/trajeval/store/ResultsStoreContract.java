package org.trajeval.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Clock;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.junit.jupiter.api.Test;
import org.trajeval.core.protocol.RegressionGate;
import org.trajeval.core.report.SuiteReport.RunEntry;

/** What every store dialect must do; run against SQLite and a real PostgreSQL. */
abstract class ResultsStoreContract {
    static final Clock CLOCK = Clock.fixed(Instant.parse("2026-11-23T08:00:00Z"), ZoneOffset.UTC);
    static final double VALUE_TOL = 1e-12;
    static final long DAY_MS = 86_400_000L;

    /** @return a fresh, empty store location */
    abstract StoreLocation freshLocation() throws Exception;

    @Test
    void recordingTheSameResultTwiceKeepsOneRow() throws Exception {
        try (ResultsStore s = ResultsStore.open(freshLocation(), CLOCK)) {
            RunRecord r = Records.run(1, "bot-1", "hall", "2.3", 1, 0.10, 0, Map.of("shift", "night"));
            assertEquals(1, s.record(List.of(r)));
            assertEquals(0, s.record(List.of(r)));
            assertEquals(1, s.count());
            RunRecord back = s.select(Selection.all()).get(0);
            assertEquals(r, back, "every column and tag reads back as written");
        }
    }

    @Test
    void selectionMatchesColumnsAndFreeTags() throws Exception {
        try (ResultsStore s = ResultsStore.open(freshLocation(), CLOCK)) {
            s.record(List.of(Records.run(1, "bot-1", "hall", "2.3", 1, 0.1, 0, Map.of("shift", "night")),
                    Records.run(2, "bot-1", "hall", "2.4", 1, 0.2, 0, Map.of("shift", "night")),
                    Records.run(3, "bot-2", "yard", "2.4", 2, 0.3, 0, Map.of("shift", "day"))));
            assertEquals(2, s.select(Selection.parse("version=2.4", "--candidate")).size());
            assertEquals(List.of("r2"), s.select(Selection.parse("software_version=2.4,shift=night", "x")).stream()
                    .map(RunRecord::runId).toList());
            assertEquals(List.of("r3"), s.select(Selection.parse("seed=2", "x")).stream().map(RunRecord::runId)
                    .toList());
        }
    }

    @Test
    void trendCellsHoldCountSumAndSquaresPerSliceAndDay() throws Exception {
        try (ResultsStore s = ResultsStore.open(freshLocation(), CLOCK)) {
            // bot-1: day 0 values 1 and 3 (mean 2, variance ((1-2)^2 + (3-2)^2) / 1 = 2); day 1 value 5
            s.record(List.of(Records.run(1, "bot-1", "hall", "2.3", 1, 1.0, 10, Map.of()),
                    Records.run(2, "bot-1", "hall", "2.3", 2, 3.0, 20, Map.of()),
                    Records.run(3, "bot-1", "hall", "2.3", 3, 5.0, DAY_MS + 5, Map.of()),
                    Records.run(4, "bot-2", "hall", "2.3", 1, 7.0, 30, Map.of())));
            List<TrendCell> cells = new ArrayList<>(s.trendCells("ate_trans_rmse_m", "robot", TrendBucket.DAY,
                    Selection.all(), 0));
            cells.sort((a, b) -> (a.slice() + a.bucket()).compareTo(b.slice() + b.bucket()));
            assertEquals(3, cells.size());
            TrendCell first = cells.get(0);
            assertEquals("bot-1", first.slice());
            assertEquals("0", first.bucket());
            assertEquals(2, first.n());
            assertEquals(2.0, first.mean(), VALUE_TOL);
            assertEquals(2.0, first.variance(), VALUE_TOL);
            assertEquals(10, first.firstMs());
            assertEquals("1", cells.get(1).bucket());
            assertEquals(7.0, cells.get(2).mean(), VALUE_TOL);
        }
    }

    @Test
    void concurrentWritersLeaveEachResultExactlyOnce() throws Exception {
        StoreLocation location = freshLocation();
        List<RunRecord> all = new ArrayList<>();
        for (int i = 0; i < 300; i++) {
            all.add(Records.run(i, "bot-" + (i % 7), "route-" + (i % 5), "2.4", i % 3, 0.01 * i, i * 1000L,
                    Map.of("k", "v" + (i % 2))));
        }
        ExecutorService pool = Executors.newFixedThreadPool(3);
        try {
            List<Future<Integer>> writers = new ArrayList<>();
            for (int w = 0; w < 3; w++) {
                long seed = w;
                writers.add(pool.submit(() -> {
                    // each writer has its own connection (as separate processes would) and its own order
                    List<RunRecord> mine = new ArrayList<>(all);
                    Collections.shuffle(mine, new Random(seed));
                    int inserted = 0;
                    try (ResultsStore s = ResultsStore.open(location, CLOCK)) {
                        for (int from = 0; from < mine.size(); from += 25) {
                            inserted += s.record(mine.subList(from, from + 25));
                        }
                    }
                    return inserted;
                }));
            }
            int inserted = 0;
            for (Future<Integer> f : writers) {
                inserted += f.get();
            }
            assertEquals(300, inserted, "the writers together inserted each result once");
        } finally {
            pool.shutdownNow();
        }
        try (ResultsStore s = ResultsStore.open(location, CLOCK)) {
            assertEquals(300, s.count());
            List<RunRecord> back = s.select(Selection.all());
            assertTrue(back.stream().allMatch(r -> r.tags().size() == 1), "every result kept its one tag");
            // the trend aggregates counted each run once: the same counts and times as the runs table,
            // sums equal up to their rounding (the values 0.01 i are not exact in binary)
            List<TrendCell> kept = sorted(s.trendCells("ate_trans_rmse_m", "robot", TrendBucket.DAY, Selection.all(),
                    0));
            List<TrendCell> raw = sorted(s.trendCellsFromRuns("ate_trans_rmse_m", "robot", TrendBucket.DAY,
                    Selection.all(), 0));
            assertEquals(raw.size(), kept.size());
            for (int i = 0; i < raw.size(); i++) {
                assertEquals(raw.get(i).n(), kept.get(i).n());
                assertEquals(raw.get(i).firstMs(), kept.get(i).firstMs());
                assertEquals(raw.get(i).lastMs(), kept.get(i).lastMs());
                assertEquals(raw.get(i).sum(), kept.get(i).sum(), VALUE_TOL);
                assertEquals(raw.get(i).sumSquares(), kept.get(i).sumSquares(), VALUE_TOL);
            }
        }
    }

    /**
     * Runs with what the trend aggregates must get right, every value a multiple of 1/64 below 4, so
     * every sum is exact in any order and the two ways of aggregating must agree to the bit: tied
     * values and tied times, 3 robots over 5 days with day 2 empty for bot-2, runs without robot or
     * version, failed runs, a non-finite value (stored as NULL), a run before the epoch, two versions.
     */
    static List<RunRecord> trendFleet() {
        Random rnd = new Random(41);
        List<RunRecord> out = new ArrayList<>();
        int id = 0;
        for (int day = 0; day < 5; day++) {
            for (int k = 0; k < 12; k++) {
                String robot = k % 4 == 3 ? null : "bot-" + (k % 4);
                if ("bot-2".equals(robot) && day == 2) {
                    continue;
                }
                String version = k == 5 ? null : day < 3 ? "2.3" : "2.4";
                boolean ok = k != 7;
                double ate = rnd.nextInt(256) / 64.0;
                Map<String, Double> m = !ok ? Map.of("score", 0.0) : k == 9 ? Map.of("ate_trans_rmse_m",
                        Double.NaN, "score", 60.0) : Map.of("ate_trans_rmse_m", ate, "rpe_trans_rmse_m", ate / 2,
                        "score", 100 - 8 * ate);
                long at = day * DAY_MS + (k / 2) * 1000L; // pairs of runs share a time
                out.add(new RunRecord(ReportRecords.sha256("trend", Integer.toString(id)), "pipeline", "r" + id++,
                        1, null, null, robot, k % 2 == 0 ? "hall" : "yard", "route-" + (k % 3), k % 2 == 0 ? "orb"
                        : "vins", version, (long) k, Instant.ofEpochMilli(at), ok, ok ? null : "diverged", m, "test",
                        Map.of()));
            }
        }
        out.add(Records.run(id, "bot-0", "route-0", "2.3", 1, 1.5, -5000, Map.of()));
        return out;
    }

    @Test
    void trendsFromTheKeptAggregatesEqualTrendsFromTheRuns() throws Exception {
        List<RunRecord> runs = trendFleet();
        try (ResultsStore s = ResultsStore.open(freshLocation(), CLOCK)) {
            // overlapping batches and a full re-recording: each run must count once
            assertEquals(40, s.record(runs.subList(0, 40)));
            assertEquals(runs.size() - 40, s.record(runs.subList(20, runs.size())));
            assertEquals(0, s.record(runs));
            assertTheAggregatesMatchTheRuns(s);
        }
    }

    @Test
    void upgradingToVersionFourFillsTheAggregatesFromTheStoredRuns() throws Exception {
        StoreLocation location = freshLocation();
        try (ResultsStore s = ResultsStore.open(location, CLOCK)) {
            s.record(trendFleet());
            // make it the store a V3 trajeval left: no trend_cells nor V5's index, V4 and V5 not recorded
            s.read("undo V4", c -> {
                try (java.sql.Statement st = c.createStatement()) {
                    st.execute("DROP TABLE trend_cells");
                    st.execute("DROP INDEX runs_by_robot_gate");
                    return st.executeUpdate("DELETE FROM trajeval_schema_migrations WHERE version >= 4");
                }
            });
        }
        try (ResultsStore s = ResultsStore.open(location, CLOCK)) {
            assertTheAggregatesMatchTheRuns(s);
        }
    }

    private static void assertTheAggregatesMatchTheRuns(ResultsStore s) {
        for (String metric : List.of("ate_trans_rmse_m", "rpe_trans_rmse_m", "score", "coverage")) {
            for (String slice : TrendCells.SLICES) {
                for (TrendBucket bucket : TrendBucket.values()) {
                    for (long since : new long[] {0, 3 * DAY_MS}) {
                        String what = metric + " by " + slice + " per " + bucket + " since " + since;
                        List<TrendCell> kept = s.trendCells(metric, slice, bucket, Selection.all(), since);
                        List<TrendCell> raw = s.trendCellsFromRuns(metric, slice, bucket, Selection.all(), since);
                        assertEquals(sorted(raw), sorted(kept), what);
                        assertEquals(Trend.analyse(raw, metric, slice, bucket, 0.95), Trend.analyse(kept, metric, slice,
                                bucket, 0.95), what);
                    }
                }
            }
        }
        // by hand: bot-2 has no day-2 cell (it ran no run that day), and the run before the epoch is in no cell
        List<TrendCell> bot2 = s.trendCells("ate_trans_rmse_m", "robot", TrendBucket.DAY, Selection.all(), 0)
                .stream().filter(c -> "bot-2".equals(c.slice())).map(c -> c).toList();
        assertEquals(List.of("0", "1", "3", "4"), bot2.stream().map(TrendCell::bucket).sorted().toList());
        assertTrue(s.trendCells("ate_trans_rmse_m", "robot", TrendBucket.DAY, Selection.all(), 0).stream()
                .allMatch(c -> c.firstMs() >= 0));
    }

    private static List<TrendCell> sorted(List<TrendCell> cells) {
        java.util.Comparator<String> nullsFirst = java.util.Comparator.nullsFirst(java.util.Comparator.naturalOrder());
        return cells.stream().sorted(java.util.Comparator.comparing(TrendCell::slice, nullsFirst)
                .thenComparing(TrendCell::bucket, nullsFirst)).toList();
    }

    @Test
    void reopeningAppliesNoMigrationTwice() throws Exception {
        StoreLocation location = freshLocation();
        try (ResultsStore s = ResultsStore.open(location, CLOCK)) {
            s.record(List.of(Records.run(1, "bot-1", "hall", "2.3", 1, 0.1, 0, Map.of())));
        }
        try (ResultsStore s = ResultsStore.open(location, CLOCK)) {
            assertEquals(1, s.count());
        }
    }

    @Test
    void theGatePairedInSqlMatchesTheGateOnTheSameRunsInJava() throws Exception {
        // the reference is RegressionGate.gateAll over the runs as suite run entries (the file gate's
        // pairing in Java); the data has what pairing must handle: seeds only one side has, repeated
        // (method, route, seed) runs, failed runs, runs without route or seed (and a route named "-",
        // which pairs with them, as in Java), a method only one side has
        Random rnd = new Random(14);
        List<RunRecord> runs = new ArrayList<>();
        int id = 0;
        for (String version : List.of("2.3", "2.4")) {
            for (String method : List.of("orb", "vins", "only-" + version)) {
                for (int route = 0; route < 6; route++) {
                    for (long seed = 1; seed <= 4; seed++) {
                        if (rnd.nextInt(5) == 0) {
                            continue; // this seed is missing on this side
                        }
                        int copies = rnd.nextInt(4) == 0 ? 2 : 1;
                        for (int k = 0; k < copies; k++) {
                            boolean ok = rnd.nextInt(10) != 0;
                            double ate = 0.1 + 0.02 * route + (version.equals("2.4") && method.equals("vins") ? 0.05
                                    : 0.0) + 0.01 * rnd.nextGaussian();
                            Map<String, Double> m = ok ? Map.of("ate_trans_rmse_m", ate, "rpe_trans_rmse_m", ate / 3,
                                    "score", 100 - 100 * ate) : Map.of("score", 0.0);
                            runs.add(new RunRecord(ReportRecords.sha256("gate", Integer.toString(id)), "suite",
                                    "r" + id, null, null, null, "bot-" + (id++ % 2), null, route == 5 ? null
                                    : route == 3 ? "-" : "route-" + route, method, version, route == 4 && seed == 1 ? null : seed,
                                    Instant.ofEpochMilli(id), ok, ok ? null : "diverged", m, "test", Map.of()));
                        }
                    }
                }
            }
        }
        Map<String, Double> tolerances = new java.util.LinkedHashMap<>();
        tolerances.put("ate_trans_rmse_m", 0.05);
        tolerances.put("rpe_trans_rmse_m", 0.10);
        tolerances.put("score", 0.05);
        RegressionGate.Settings settings = new RegressionGate.Settings(0.95, 3, 500);
        try (ResultsStore s = ResultsStore.open(freshLocation(), CLOCK)) {
            s.record(runs);
            for (GatePairing pairing : GatePairing.values()) {
                Selection b = Selection.parse("version=2.3", "--baseline");
                Selection c = Selection.parse("version=2.4", "--candidate");
                StoredGate.Result sql = StoredGate.gate(s, b, c, pairing, tolerances, settings);
                assertEquals(List.of("orb", "vins"), sql.methods());
                List<RunEntry> be = entries(s.select(b), pairing);
                List<RunEntry> ce = entries(s.select(c), pairing);
                List<String> seqs = be.stream().map(RunEntry::sequence).distinct().sorted().toList();
                assertEquals(seqs.size(), sql.baselineSequences());
                List<RegressionGate.Finding> java = RegressionGate.gateAll(be, ce, sql.methods(), seqs, tolerances,
                        settings);
                assertEquals(java.size(), sql.findings().size());
                for (int i = 0; i < java.size(); i++) {
                    RegressionGate.Finding j = java.get(i);
                    RegressionGate.Finding q = sql.findings().get(i);
                    String what = pairing + " " + j.method() + " " + j.metric();
                    assertEquals(j.n(), q.n(), what);
                    assertEquals(j.baselineMean(), q.baselineMean(), VALUE_TOL, what);
                    assertEquals(j.candidateMean(), q.candidateMean(), VALUE_TOL, what);
                    assertEquals(j.bound(), q.bound(), VALUE_TOL, what);
                    assertEquals(j.verdict(), q.verdict(), what);
                }
                assertEquals(RegressionGate.Verdict.REGRESSION, sql.findings().get(3).verdict(),
                        "vins is 0.05 m worse on 2.4, beyond 5 % of about 0.15 m");
            }
        }
    }

    /** Stored runs as suite run entries, the pairing's sequence and seed as theirs (the reference path). */
    private static List<RunEntry> entries(List<RunRecord> records, GatePairing pairing) {
        List<RunEntry> out = new ArrayList<>();
        for (RunRecord r : records) {
            String route = r.route() == null ? "-" : r.route();
            String sequence = pairing == GatePairing.ROBOT_ROUTE ? r.robot() + "/" + route : route;
            long seed = pairing == GatePairing.ROBOT_ROUTE || r.seed() == null ? 0 : r.seed();
            out.add(new RunEntry(r.method(), sequence, seed, "test", null, r.ok() ? "ok" : "failed", null, null,
                    r.metrics(), r.metric(StoredMetric.SCORE), null));
        }
        return out;
    }
}
