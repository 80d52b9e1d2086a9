package org.trajeval.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The store contract on the embedded SQLite default, plus what is SQLite's own. */
class SqliteStoreTest extends ResultsStoreContract {
    private static final String ROBOT_GATE = "USING COVERING INDEX runs_by_robot_gate (robot=? AND software_version=?)";
    @TempDir
    Path dir;
    private int count;

    @Override
    StoreLocation freshLocation() {
        return StoreLocation.sqlite(dir.resolve("store" + (count++) + ".db"));
    }

    @Test
    void theFileIsInWalModeWithTheMigrationRecorded() throws Exception {
        StoreLocation loc = freshLocation();
        ResultsStore.open(loc, CLOCK).close();
        try (Connection c = DriverManager.getConnection(loc.jdbcUrl()); Statement s = c.createStatement()) {
            try (ResultSet rs = s.executeQuery("PRAGMA journal_mode")) {
                rs.next();
                assertEquals("wal", rs.getString(1));
            }
            try (ResultSet rs = s.executeQuery("SELECT version, name FROM trajeval_schema_migrations")) {
                assertTrue(rs.next());
                assertEquals(1, rs.getInt(1));
                assertEquals("V1__runs.sql", rs.getString(2));
            }
        }
    }

    @Test
    void openingWaitsForAnotherConnectionsLockInsteadOfFailingBusy() throws Exception {
        // SQLite answers the switch to WAL with SQLITE_BUSY at once, without its busy handler, while
        // another connection holds a lock: two processes opening a fresh store at the same moment
        StoreLocation loc = freshLocation();
        try (Connection other = DriverManager.getConnection(loc.jdbcUrl()); Statement s = other.createStatement()) {
            s.executeUpdate("CREATE TABLE held (x)");
            other.setAutoCommit(false);
            s.executeQuery("SELECT count(*) FROM held").close();
            s.executeUpdate("INSERT INTO held VALUES (1)");
            java.util.concurrent.CompletableFuture<Void> opened = java.util.concurrent.CompletableFuture.runAsync(
                    () -> ResultsStore.open(loc, CLOCK).close());
            Thread.sleep(300);
            assertTrue(!opened.isDone(), "the store waits while the other connection writes");
            other.commit();
            opened.get(30, java.util.concurrent.TimeUnit.SECONDS);
        }
        try (Connection c = DriverManager.getConnection(loc.jdbcUrl()); Statement s = c.createStatement();
                ResultSet rs = s.executeQuery("PRAGMA journal_mode")) {
            rs.next();
            assertEquals("wal", rs.getString(1));
        }
    }

    @Test
    void aChangedMigrationIsRefused() throws Exception {
        StoreLocation loc = freshLocation();
        ResultsStore.open(loc, CLOCK).close();
        try (Connection c = DriverManager.getConnection(loc.jdbcUrl()); Statement s = c.createStatement()) {
            s.executeUpdate("UPDATE trajeval_schema_migrations SET sha256 = 'x' WHERE version = 1");
        }
        StoreException e = assertThrows(StoreException.class, () -> ResultsStore.open(loc, CLOCK));
        assertEquals(StoreException.Problem.SCHEMA, e.problem());
        assertTrue(e.getMessage().contains("V1__runs.sql was changed after it was applied"), e.getMessage());
    }

    @Test
    void aNewerSchemaIsRefused() throws Exception {
        StoreLocation loc = freshLocation();
        ResultsStore.open(loc, CLOCK).close();
        try (Connection c = DriverManager.getConnection(loc.jdbcUrl()); Statement s = c.createStatement()) {
            s.executeUpdate("INSERT INTO trajeval_schema_migrations VALUES (99, 'V99__future.sql', 'x', 'now')");
        }
        StoreException e = assertThrows(StoreException.class, () -> ResultsStore.open(loc, CLOCK));
        assertEquals(StoreException.Problem.SCHEMA, e.problem());
        assertTrue(e.getMessage().contains("version 99, newer than this trajeval knows (" + Migrations.latest() + ")"),
                e.getMessage());
    }

    @Test
    void aVersionOneStoreIsUpgradedToVersionTwoKeepingItsRows() throws Exception {
        StoreLocation loc = freshLocation();
        try (ResultsStore s = ResultsStore.open(loc, CLOCK)) {
            s.record(java.util.List.of(Records.run(1, "bot-1", "hall", "2.3", 1, 0.1, 0, java.util.Map.of())));
        }
        // make it the store an earlier trajeval left: V2 neither applied nor recorded
        try (Connection c = DriverManager.getConnection(loc.jdbcUrl()); Statement s = c.createStatement()) {
            s.executeUpdate("DROP INDEX runs_by_site");
            s.executeUpdate("DROP INDEX runs_by_version_gate");
            s.executeUpdate("CREATE INDEX runs_by_version ON runs (software_version, method, route, seed)");
            s.executeUpdate("DELETE FROM trajeval_schema_migrations WHERE version = 2");
        }
        try (ResultsStore s = ResultsStore.open(loc, CLOCK)) {
            assertEquals(1, s.count());
        }
        try (Connection c = DriverManager.getConnection(loc.jdbcUrl()); Statement s = c.createStatement()) {
            try (ResultSet rs = s.executeQuery("SELECT name FROM trajeval_schema_migrations ORDER BY version")) {
                assertTrue(rs.next());
                assertEquals("V1__runs.sql", rs.getString(1));
                assertTrue(rs.next());
                assertEquals("V2__site_version_tags.sql", rs.getString(1));
            }
            try (ResultSet rs = s.executeQuery("SELECT name FROM sqlite_master WHERE type = 'index' "
                    + "AND name LIKE 'runs_by_%' ORDER BY name")) {
                java.util.List<String> names = new java.util.ArrayList<>();
                while (rs.next()) {
                    names.add(rs.getString(1));
                }
                // runs_by_domain is V3's (still applied: only V2 was undone above)
                // runs_by_robot_gate is V5's
                assertEquals(java.util.List.of("runs_by_domain", "runs_by_robot", "runs_by_robot_gate",
                        "runs_by_route", "runs_by_site", "runs_by_time", "runs_by_version_gate"), names,
                        "V2's indexes, V1's runs_by_version replaced");
            }
        }
    }

    @Test
    void aVersionTwoStoreIsUpgradedToVersionThreeKeepingItsRows() throws Exception {
        StoreLocation loc = freshLocation();
        try (ResultsStore s = ResultsStore.open(loc, CLOCK)) {
            s.record(java.util.List.of(Records.run(1, "bot-1", "hall", "2.3", 1, 0.1, 0, java.util.Map.of())));
        }
        // make it the store a V2 trajeval left: V3's columns and index gone, V3 not recorded
        try (Connection c = DriverManager.getConnection(loc.jdbcUrl()); Statement s = c.createStatement()) {
            s.executeUpdate("DROP INDEX runs_by_domain");
            for (String col : new String[] {"domain", "scenario", "simulator", "environment", "modality",
                "ground_truth", "factors", "wall_time_s", "peak_memory_mib"}) {
                s.executeUpdate("ALTER TABLE runs DROP COLUMN " + col);
            }
            s.executeUpdate("DELETE FROM trajeval_schema_migrations WHERE version = 3");
        }
        try (ResultsStore s = ResultsStore.open(loc, CLOCK)) {
            assertEquals(1, s.count());
        }
        try (Connection c = DriverManager.getConnection(loc.jdbcUrl()); Statement s = c.createStatement();
                ResultSet rs = s.executeQuery("SELECT domain, wall_time_s FROM runs")) {
            assertTrue(rs.next());
            assertEquals(null, rs.getString(1), "rows recorded before V3 have no description");
        }
    }

    @Test
    void aGateOnOneRobotReadsTheRobotIndexOnceTheStatisticsAreKept() throws Exception {
        // 20 robots x 5 versions x 20 runs. Without statistics SQLite prefers the version index (whose order
        // serves the GROUP BY) and then reads every run of the version from the table to test its robot (at
        // 10^6 runs: 10^5 rows, 1.8 s); with the statistics the store's PRAGMA optimize keeps after a large
        // batch it reads the 20 runs of (robot, version) from V5's index alone (tried by hand: without the pragma
        // the plan below names runs_by_version_gate). The plan is checked, not a time.
        StoreLocation loc = freshLocation();
        java.util.List<RunRecord> runs = new java.util.ArrayList<>();
        for (int i = 0; i < 2000; i++) {
            runs.add(Records.run(i, "bot-" + (i % 20), "route-" + (i % 7), "v" + (i / 400), i % 5, 0.1, i * 1000L,
                    java.util.Map.of()));
        }
        try (ResultsStore s = ResultsStore.open(loc, CLOCK)) {
            s.record(runs);
            Selection base = Selection.parse("software_version=v3,robot=bot-7", "--baseline");
            Selection cand = Selection.parse("software_version=v4,robot=bot-7", "--candidate");
            for (GatePairing pairing : GatePairing.values()) {
                java.util.List<Object> args = new java.util.ArrayList<>();
                String plan = plan(s, StoredGate.pairedSql(base, cand, pairing, java.util.List.of("ate_trans_rmse_m"),
                        args), args);
                assertTrue(plan.contains(ROBOT_GATE) && !plan.contains("runs_by_version_gate"), plan);
                args.clear();
                plan = plan(s, StoredGate.sideSql(base, pairing, args), args);
                assertTrue(plan.contains(ROBOT_GATE) && !plan.contains("runs_by_version_gate"), plan);
            }
        }
    }

    /** @return SQLite's EXPLAIN QUERY PLAN of a query, one line per step */
    private static String plan(ResultsStore s, String sql, java.util.List<Object> args) {
        return s.read("explain", c -> {
            try (java.sql.PreparedStatement st = c.prepareStatement("EXPLAIN QUERY PLAN " + sql)) {
                ResultsStore.bindAll(st, args);
                StringBuilder out = new StringBuilder();
                try (ResultSet rs = st.executeQuery()) {
                    while (rs.next()) {
                        out.append(rs.getString(4)).append('\n');
                    }
                }
                return out.toString();
            }
        });
    }
}
