package org.trajeval.store;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.function.Supplier;
import org.trajeval.core.protocol.RegressionGate;

/**
 * The README's store figures: {@code gradle :store:measure [-Pargs="RUNS sqlite|postgresql [FILE]"]}
 * (FILE: a SQLite store kept after the run and reused, unfilled, when it already holds RUNS runs).
 * Fills a fresh store with RUNS synthetic run results (50 robots, 5 sites, 20 routes, 3 methods,
 * 10 software versions over 100 days, seeds 1-5; one tag each), then times the trend queries and
 * the gate (pairing and per-sequence sums in SQL, then the paired statistics): 7 repetitions, wall time
 * min, median and max and the minimum CPU time of the querying thread, with the load average before
 * and after. {@code bench/store-measure.sh} runs both databases.
 */
public final class StoreMeasure {
    private StoreMeasure() {
    }

    public static void main(String[] args) throws Exception {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 1_000_000;
        String dialect = args.length > 1 ? args[1] : "sqlite";
        Path dir = Files.createTempDirectory("trajeval-store-measure");
        PostgresServer pg = null;
        StoreLocation loc;
        if ("postgresql".equals(dialect)) {
            pg = PostgresServer.start(false);
            loc = StoreLocation.parse(pg.url(""), pg.env());
        } else {
            loc = StoreLocation.sqlite(args.length > 2 ? Path.of(args[2]) : dir.resolve("measure.db"));
        }
        try (ResultsStore s = ResultsStore.open(loc, Clock.systemUTC())) {
            if (s.count() != runs) {
                fill(s, runs, dialect, loc);
            } else {
                System.out.printf(Locale.ROOT, "%s: reusing %s (%d runs)%n", dialect, loc.display(), runs);
            }
            long start = Instant.parse("2026-08-01T00:00:00Z").toEpochMilli();
            long span = 100L * 86_400_000L;
            measureQueries(s, start, span);
        } finally {
            if (pg != null) {
                pg.close();
            }
            try (var st = Files.walk(dir)) {
                st.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
            }
        }
    }

    private static void fill(ResultsStore s, int runs, String dialect, StoreLocation loc) throws Exception {
        long t0 = System.nanoTime();
        Random rnd = new Random(1);
        List<RunRecord> batch = new ArrayList<>();
        long start = Instant.parse("2026-08-01T00:00:00Z").toEpochMilli();
        long span = 100L * 86_400_000L;
        for (int i = 0; i < runs; i++) {
            long at = start + (long) ((double) i / runs * span);
            int version = (int) ((long) i * 10 / runs);
            int method = i % 3;
            double ate = (0.08 + 0.02 * method) * (1 + 0.2 * rnd.nextGaussian() * 0.5);
            batch.add(new RunRecord(ReportRecords.sha256("measure", Integer.toString(i)), "pipeline", "r" + i, 1,
                    null, null, "bot-" + (i % 50), "site-" + (i % 5), "route-" + ((i / 3) % 20),
                    "m" + method, "v" + version, (long) (1 + (i / 60) % 5), Instant.ofEpochMilli(at), true, null,
                    Map.of("ate_trans_rmse_m", ate, "rpe_trans_rmse_m", ate / 3), "measure",
                    Map.of("shift", i % 2 == 0 ? "day" : "night")));
            if (batch.size() == 10_000) {
                s.record(batch);
                batch.clear();
            }
        }
        s.record(batch);
        double insertS = (System.nanoTime() - t0) / 1e9;
        System.out.printf(Locale.ROOT, "%s: %d runs recorded in %.1f s (%.0f runs/s); count %d%s%n", dialect,
                runs, insertS, runs / insertS, s.count(), "sqlite".equals(dialect)
                        ? String.format(Locale.ROOT, "; file %.0f MB", Files.size(Path.of(loc.jdbcUrl()
                                .substring("jdbc:sqlite:".length()))) / 1e6)
                        : "");
        long a0 = System.nanoTime();
        s.optimize(); // what db import does after a bulk load
        System.out.printf(Locale.ROOT, "%s: statistics after the load (optimize) %.1f s%n", dialect,
                (System.nanoTime() - a0) / 1e9);
    }

    private static void measureQueries(ResultsStore s, long start, long span) {
        System.out.println("load average before the queries (1, 5, 15 min): " + load());
        time("trend ate by robot per day (all runs)", () -> Trend.of(s, "ate_trans_rmse_m", "robot",
                TrendBucket.DAY, Selection.all(), 0, 0.95).slices().size());
        time("trend ate by route per version", () -> Trend.of(s, "ate_trans_rmse_m", "route",
                TrendBucket.VERSION, Selection.all(), 0, 0.95).slices().size());
        time("trend ate by robot per day, site=site-3, last 14 days", () -> Trend.of(s, "ate_trans_rmse_m",
                "robot", TrendBucket.DAY, Selection.parse("site=site-3", "x"), start + span - 14 * 86_400_000L,
                0.95).slices().size());
        time("gate v8 vs v9 (paired in SQL + paired statistics)", () -> gate(s, "v8", "v9"));
        time("gate v8 vs v9: its SQL alone (both sides' counts + pairing)", () -> {
            Selection b = Selection.parse("software_version=v8", "b");
            Selection c = Selection.parse("software_version=v9", "c");
            return StoredGate.sideCells(s, b, GatePairing.ROUTE_SEED).size() + StoredGate.sideCells(s, c,
                    GatePairing.ROUTE_SEED).size() + StoredGate.pairedCells(s, b, c, GatePairing.ROUTE_SEED,
                    List.of("ate_trans_rmse_m", "rpe_trans_rmse_m")).size();
        });
        time("gate v8 vs v9 on robot bot-7 only", () -> gate(s, "v8,robot=bot-7", "v9,robot=bot-7"));
        System.out.println("load average after the queries (1, 5, 15 min): " + load());
    }

    /** @return the machine's load averages, {@code /proc/loadavg}'s first three fields */
    private static String load() {
        try {
            String[] f = Files.readString(Path.of("/proc/loadavg")).split(" ");
            return f[0] + " " + f[1] + " " + f[2];
        } catch (java.io.IOException e) {
            return "unknown";
        }
    }

    private static int gate(ResultsStore s, String base, String cand) {
        return StoredGate.gate(s, Selection.parse("software_version=" + base, "b"),
                Selection.parse("software_version=" + cand, "c"), GatePairing.ROUTE_SEED,
                new java.util.LinkedHashMap<>(Map.of("ate_trans_rmse_m", 0.05, "rpe_trans_rmse_m", 0.05)),
                new RegressionGate.Settings(0.95, 1, 4000)).findings().size();
    }

    /**
     * Runs a query 7 times: wall time min, median, max, and the minimum CPU time of this thread
     * (SQLite runs inside it, so that is the query's own work whatever the machine's load;
     * PostgreSQL's work is in the server process and not counted).
     */
    private static void time(String what, Supplier<Integer> q) {
        java.lang.management.ThreadMXBean cpu = java.lang.management.ManagementFactory.getThreadMXBean();
        double[] t = new double[7];
        double minCpu = Double.MAX_VALUE;
        int result = 0;
        for (int i = 0; i < t.length; i++) {
            long c0 = cpu.getCurrentThreadCpuTime();
            long t0 = System.nanoTime();
            result = q.get();
            t[i] = (System.nanoTime() - t0) / 1e6;
            minCpu = Math.min(minCpu, (cpu.getCurrentThreadCpuTime() - c0) / 1e6);
        }
        Arrays.sort(t);
        System.out.printf(Locale.ROOT, "  %-62s wall min %7.1f, median %7.1f, max %7.1f ms; CPU min %7.1f ms [%d]%n",
                what, t[0], t[3], t[6], minCpu, result);
    }
}
