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
                assertEquals(java.util.List.of("runs_by_domain", "runs_by_robot", "runs_by_route", "runs_by_site",
                        "runs_by_time", "runs_by_version_gate"), names, "V2's indexes, V1's runs_by_version replaced");
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
}
