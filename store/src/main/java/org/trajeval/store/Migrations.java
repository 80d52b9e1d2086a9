package org.trajeval.store;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.time.Clock;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * The store's schema as ordered, immutable SQL files ({@code migrations/V1__runs.sql}, Flyway's
 * naming), applied in order inside one transaction and recorded in
 * {@code trajeval_schema_migrations (version, name, sha256, applied_at)}.
 *
 * <p>Why not Flyway: the same plain files work on SQLite and PostgreSQL without a second
 * database module, the runner is 100 lines, and the CLI's start-up stays free of Flyway's class
 * scanning. Flyway could adopt these files unchanged (its naming and checksum idea are kept).
 *
 * <p>Concurrency: PostgreSQL holds an advisory transaction lock, SQLite an IMMEDIATE
 * transaction, so two processes opening a new store at once apply each migration once.
 */
final class Migrations {
    /** The migrations in order; index i holds version i + 1. */
    static final List<String> FILES = List.of("V1__runs.sql", "V2__site_version_tags.sql",
            "V3__run_description.sql", "V4__trend_cells.sql",
            "V5__robot_gate_index.sql");
    private static final long ADVISORY_LOCK = 0x7472616a6576616cL; // "trajeval"

    private Migrations() {
    }

    /** @return the newest schema version this code knows */
    static int latest() {
        return FILES.size();
    }

    /**
     * Brings the schema to {@link #latest()}; the connection is left in auto-commit mode.
     *
     * @return how many migrations were applied now
     */
    static int migrate(Connection c, Dialect dialect, Clock clock, String display) throws SQLException {
        c.setAutoCommit(false);
        try (Statement s = c.createStatement()) {
            if (dialect == Dialect.POSTGRESQL) {
                s.execute("SELECT pg_advisory_xact_lock(" + ADVISORY_LOCK + ")");
            }
            s.execute("CREATE TABLE IF NOT EXISTS trajeval_schema_migrations (version INTEGER NOT NULL PRIMARY KEY, "
                    + "name TEXT NOT NULL, sha256 CHAR(64) NOT NULL, applied_at TEXT NOT NULL)");
            Map<Integer, String[]> applied = new TreeMap<>();
            int appliedNow = 0;
            try (ResultSet rs = s.executeQuery("SELECT version, name, sha256 FROM trajeval_schema_migrations")) {
                while (rs.next()) {
                    applied.put(rs.getInt(1), new String[] {rs.getString(2), rs.getString(3)});
                }
            }
            for (int v : applied.keySet()) {
                if (v > latest()) {
                    throw new StoreException(StoreException.Problem.SCHEMA, display + ": the store's schema is at "
                            + "version " + v + ", newer than this trajeval knows (" + latest() + "); upgrade trajeval",
                            null);
                }
            }
            for (int i = 0; i < FILES.size(); i++) {
                String name = FILES.get(i);
                String sql = load(name);
                String sha = sha256(sql);
                String[] done = applied.get(i + 1);
                if (done != null) {
                    if (!done[1].equals(sha)) {
                        throw new StoreException(StoreException.Problem.SCHEMA, display + ": migration " + name
                                + " was changed after it was applied (SHA-256 " + done[1] + " in the store, " + sha
                                + " now); migrations are immutable, add a new one", null);
                    }
                    continue;
                }
                for (String statement : statements(sql)) {
                    s.execute(statement);
                }
                try (PreparedStatement p = c.prepareStatement("INSERT INTO trajeval_schema_migrations "
                        + "(version, name, sha256, applied_at) VALUES (?, ?, ?, ?)")) {
                    p.setInt(1, i + 1);
                    p.setString(2, name);
                    p.setString(3, sha);
                    p.setString(4, clock.instant().toString());
                    p.executeUpdate();
                }
                appliedNow++;
            }
            c.commit();
            return appliedNow;
        } catch (SQLException | RuntimeException e) {
            c.rollback();
            throw e;
        } finally {
            c.setAutoCommit(true);
        }
    }

    /** @return the statements of a migration file: split at semicolons ending a line, comments dropped */
    static List<String> statements(String sql) {
        List<String> out = new ArrayList<>();
        StringBuilder cur = new StringBuilder();
        for (String line : sql.split("\n")) {
            String t = line.strip();
            if (t.startsWith("--") || t.isEmpty()) {
                continue;
            }
            cur.append(line).append('\n');
            if (t.endsWith(";")) {
                String st = cur.toString().strip();
                out.add(st.substring(0, st.length() - 1));
                cur.setLength(0);
            }
        }
        if (!cur.toString().isBlank()) {
            out.add(cur.toString().strip());
        }
        return out;
    }

    static String load(String name) {
        try (InputStream in = Migrations.class.getResourceAsStream("migrations/" + name)) {
            if (in == null) {
                throw new IllegalStateException("migration " + name + " is missing from the class path");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalStateException("cannot read migration " + name, e);
        }
    }

    static String sha256(String text) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256")
                    .digest(text.getBytes(StandardCharsets.UTF_8)));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("the JDK has no SHA-256", e);
        }
    }
}
