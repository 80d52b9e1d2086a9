package org.trajeval.store;

import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.time.Clock;
import java.util.ArrayList;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Properties;
import java.util.Set;
import org.trajeval.core.io.sqlite.SqliteNativeLibrary;

/**
 * The results store: run results in one SQL schema on SQLite or PostgreSQL, through plain JDBC
 * with prepared statements. Opening migrates the schema ({@link Migrations}). Recording is
 * idempotent: rows are keyed by {@link RunRecord#resultSha256()} and inserted with
 * {@code ON CONFLICT DO NOTHING} (both databases accept it), so any number of writers may record
 * the same results at once and each stays exactly once.
 *
 * <p>SQLite runs in WAL mode (readers never block the writer, several processes on one host may
 * write; writes wait up to 30 s for the lock) with {@code synchronous=NORMAL}: a power cut may
 * lose the last transactions, never corrupt the file, and the report files rebuild them.
 * One connection per store; methods are synchronized, so one store may serve several threads.
 */
public final class ResultsStore implements AutoCloseable {
    /** Runs inserted through one connection after which SQLite's statistics are brought up to date. */
    static final int OPTIMIZE_EVERY = 1000;

    private final StoreLocation location;
    private final Connection connection;
    private long insertedSinceOptimize;

    private ResultsStore(StoreLocation location, Connection connection) {
        this.location = location;
        this.connection = connection;
    }

    /**
     * Connects and brings the schema up to date.
     *
     * @throws StoreException UNAVAILABLE when the database cannot be reached or refuses the login,
     *     SCHEMA when its schema is newer or was tampered with
     */
    public static ResultsStore open(StoreLocation location, Clock clock) {
        Properties p = location.connectionProperties();
        if (location.dialect() == Dialect.SQLITE) {
            // the driver's native library from a fixed file, not a fresh copy in /tmp at every start
            try {
                SqliteNativeLibrary.configure(System.getenv());
            } catch (IllegalStateException e) {
                throw new StoreException(StoreException.Problem.UNAVAILABLE, e.getMessage(), e);
            }
            // WAL is switched on after connecting (SqliteWal), waiting for other connections' locks
            p.setProperty("synchronous", "NORMAL");
            p.setProperty("busy_timeout", Integer.toString(SqliteWal.BUSY_TIMEOUT_MS));
            p.setProperty("transaction_mode", "IMMEDIATE");
            p.setProperty("foreign_keys", "true");
        } else {
            p.setProperty("connectTimeout", "10");
            p.setProperty("ApplicationName", "trajeval");
        }
        Connection c;
        try {
            c = DriverManager.getConnection(location.jdbcUrl(), p);
        } catch (SQLException e) {
            throw new StoreException(StoreException.Problem.UNAVAILABLE, location.display()
                    + ": cannot connect (" + oneLine(e) + ")", e);
        }
        try {
            if (location.dialect() == Dialect.SQLITE) {
                enableWal(c, location);
            }
            int migrated = Migrations.migrate(c, location.dialect(), clock, location.display());
            ResultsStore store = new ResultsStore(location, c);
            if (location.dialect() == Dialect.SQLITE) {
                // after a migration, statistics for its new tables and indexes (ANALYZE, each index sampled
                // at most 1000 rows deep); else for every table whose size changed 25-fold since its last
                // ANALYZE (SQLite bounds the work): the planner then picks the robot index for a gate on one robot
                if (migrated > 0) {
                    store.sqliteOptimize("PRAGMA analysis_limit=1000", "ANALYZE");
                } else {
                    store.sqliteOptimize("PRAGMA optimize=0x10002");
                }
            }
            return store;
        } catch (SQLException e) {
            closeQuietly(c);
            throw new StoreException(StoreException.Problem.UNAVAILABLE, location.display()
                    + ": cannot create or upgrade the schema (" + oneLine(e) + ")", e);
        } catch (RuntimeException e) {
            closeQuietly(c);
            throw e;
        }
    }

    private static void enableWal(Connection c, StoreLocation location) {
        try {
            SqliteWal.enable(c);
        } catch (SQLException e) {
            closeQuietly(c);
            throw new StoreException(StoreException.Problem.UNAVAILABLE, location.display()
                    + ": cannot switch to WAL mode (" + oneLine(e) + ")", e);
        }
    }

    /** @return where this store lives */
    public StoreLocation location() {
        return location;
    }

    /** @return the schema version in use */
    public static int schemaVersion() {
        return Migrations.latest();
    }

    /**
     * Records results in one transaction; results already present (same key) are left as they are.
     *
     * @return how many results were new
     */
    public synchronized int record(Collection<RunRecord> records) {
        if (records.isEmpty()) {
            return 0;
        }
        // one lock order for every writer (rows by key, then their tags): concurrent writers of
        // overlapping batches then wait for each other instead of deadlocking (PostgreSQL detects a
        // deadlock and aborts one; a retry would do, but the order avoids it)
        List<RunRecord> list = new ArrayList<>(records);
        list.sort(java.util.Comparator.comparing(RunRecord::resultSha256));
        for (int attempt = 1;; attempt++) {
            try {
                int inserted = insert(list);
                insertedSinceOptimize += inserted;
                if (insertedSinceOptimize >= OPTIMIZE_EVERY && location.dialect() == Dialect.SQLITE) {
                    autoCommit();
                    sqliteOptimize("PRAGMA optimize=0x10002");
                }
                return inserted;
            } catch (SQLException e) {
                rollbackQuietly();
                String state = e.getSQLState();
                boolean transientConflict = "40001".equals(state) || "40P01".equals(state);
                if (!transientConflict || attempt >= 3) {
                    throw failure("cannot record results", e);
                }
            } finally {
                autoCommit();
            }
        }
    }

    private int insert(List<RunRecord> list) throws SQLException {
        connection.setAutoCommit(false);
        int inserted = 0;
        {
            try (PreparedStatement runs = connection.prepareStatement(RunRows.INSERT);
                    PreparedStatement tags = connection.prepareStatement("INSERT INTO run_tags (result_sha256, tag, "
                            + "value) VALUES (?, ?, ?) ON CONFLICT (result_sha256, tag) DO NOTHING")) {
                for (RunRecord r : list) {
                    RunRows.bind(runs, r);
                    runs.addBatch();
                }
                int[] counts = runs.executeBatch();
                boolean anyTags = false;
                List<RunRecord> fresh = new ArrayList<>();
                for (int i = 0; i < list.size(); i++) {
                    if (counts[i] < 0) {
                        // both drivers report each row's count (the PostgreSQL driver unless reWriteBatchedInserts
                        // is on, which the store never sets); without it the trend aggregates could double count
                        throw new IllegalStateException("the JDBC driver gave no row count for a recorded result");
                    }
                    if (counts[i] > 0) {
                        inserted += counts[i];
                        fresh.add(list.get(i));
                    }
                    for (Map.Entry<String, String> t : list.get(i).tags().entrySet()) {
                        tags.setString(1, list.get(i).resultSha256());
                        tags.setString(2, t.getKey());
                        tags.setString(3, t.getValue());
                        tags.addBatch();
                        anyTags = true;
                    }
                }
                if (anyTags) {
                    tags.executeBatch();
                }
                TrendCells.add(connection, fresh);
            }
        }
        connection.commit();
        return inserted;
    }

    /**
     * Brings the planner's statistics up to date after a bulk load ({@code db import}): SQLite
     * {@code PRAGMA optimize} (an ANALYZE where the tables changed, bounded by SQLite), PostgreSQL
     * {@code VACUUM (ANALYZE)} of the store's tables (statistics, and the visibility map its
     * index-only scans need; autovacuum would get there later).
     */
    public synchronized void optimize() {
        try (java.sql.Statement s = connection.createStatement()) {
            if (location.dialect() == Dialect.SQLITE) {
                s.execute("PRAGMA optimize=0x10002");
                insertedSinceOptimize = 0;
                return;
            }
            for (String table : List.of("runs", "run_tags", "trend_cells")) {
                s.execute("VACUUM (ANALYZE) " + table);
            }
        } catch (SQLException e) {
            throw failure("cannot analyse the tables", e);
        }
    }

    /** Runs a statistics pragma; quietly, as statistics only guide the planner (a failing store fails its next call). */
    private void sqliteOptimize(String... pragmas) {
        insertedSinceOptimize = 0;
        try (java.sql.Statement s = connection.createStatement()) {
            for (String pragma : pragmas) {
                s.execute(pragma);
            }
        } catch (SQLException ignored) {
            // the planner keeps the statistics it had
        }
    }

    /** @return which of these keys are stored */
    public synchronized Set<String> present(Collection<String> keys) {
        Set<String> out = new HashSet<>();
        List<String> list = new ArrayList<>(keys);
        final int chunk = 500;
        try {
            for (int from = 0; from < list.size(); from += chunk) {
                List<String> part = list.subList(from, Math.min(list.size(), from + chunk));
                String in = "?" + ", ?".repeat(part.size() - 1);
                try (PreparedStatement s = connection.prepareStatement(
                        "SELECT result_sha256 FROM runs WHERE result_sha256 IN (" + in + ")")) {
                    for (int i = 0; i < part.size(); i++) {
                        s.setString(i + 1, part.get(i));
                    }
                    try (ResultSet rs = s.executeQuery()) {
                        while (rs.next()) {
                            out.add(rs.getString(1));
                        }
                    }
                }
            }
            return out;
        } catch (SQLException e) {
            throw failure("cannot look results up", e);
        }
    }

    /** @return the number of stored results */
    public synchronized long count() {
        try (PreparedStatement s = connection.prepareStatement("SELECT COUNT(*) FROM runs");
                ResultSet rs = s.executeQuery()) {
            rs.next();
            return rs.getLong(1);
        } catch (SQLException e) {
            throw failure("cannot count results", e);
        }
    }

    /** @return every stored result the selection takes (tags included), ordered by method, route, seed, key */
    public List<RunRecord> select(Selection selection) {
        return select(selection, true);
    }

    /**
     * @param withTags whether to read the tags too (the gate needs none: one query instead of one per 500 rows)
     * @return every stored result the selection takes, ordered by method, route, seed, key
     */
    public synchronized List<RunRecord> select(Selection selection, boolean withTags) {
        StringBuilder sql = new StringBuilder("SELECT ").append(RunRows.COLUMNS).append(" FROM runs r WHERE 1 = 1");
        List<Object> args = new ArrayList<>();
        selection.appendWhere(sql, args);
        sql.append(" ORDER BY method, route, seed, r.result_sha256");
        try (PreparedStatement s = connection.prepareStatement(sql.toString())) {
            bindAll(s, args);
            List<RunRecord> rows = new ArrayList<>();
            try (ResultSet rs = s.executeQuery()) {
                while (rs.next()) {
                    rows.add(RunRows.read(rs));
                }
            }
            return withTags ? withTags(rows) : rows;
        } catch (SQLException e) {
            throw failure("cannot select results " + selection, e);
        }
    }

    private List<RunRecord> withTags(List<RunRecord> rows) throws SQLException {
        if (rows.isEmpty()) {
            return rows;
        }
        Map<String, Map<String, String>> tags = new HashMap<>();
        List<String> keys = rows.stream().map(RunRecord::resultSha256).toList();
        final int chunk = 500;
        for (int from = 0; from < keys.size(); from += chunk) {
            List<String> part = keys.subList(from, Math.min(keys.size(), from + chunk));
            try (PreparedStatement s = connection.prepareStatement("SELECT result_sha256, tag, value FROM run_tags "
                    + "WHERE result_sha256 IN (?" + ", ?".repeat(part.size() - 1) + ")")) {
                for (int i = 0; i < part.size(); i++) {
                    s.setString(i + 1, part.get(i));
                }
                try (ResultSet rs = s.executeQuery()) {
                    while (rs.next()) {
                        tags.computeIfAbsent(rs.getString(1), k -> new HashMap<>()).put(rs.getString(2),
                                rs.getString(3));
                    }
                }
            }
        }
        if (tags.isEmpty()) {
            return rows;
        }
        List<RunRecord> out = new ArrayList<>(rows.size());
        for (RunRecord r : rows) {
            Map<String, String> t = tags.get(r.resultSha256());
            out.add(t == null ? r : new RunRecord(r.resultSha256(), r.origin(), r.runId(), r.runVersion(),
                    r.contentSha256(), r.dataset(), r.robot(), r.site(), r.route(), r.method(), r.softwareVersion(),
                    r.seed(), r.recordedAt(), r.ok(), r.failureReason(), r.metrics(), r.source(), t));
        }
        return out;
    }

    /**
     * Aggregates a metric per slice and bucket over successful runs: count, sum and sum of squares,
     * so only the cells leave the database. A whole-history trend ({@link TrendCells#serves}) sums
     * the kept aggregates of schema v4; any other is aggregated from the runs
     * ({@link #trendCellsFromRuns}); both give the same cells.
     *
     * @param metric a metric column
     * @param slice a label column ({@link Selection#COLUMNS}) to slice by
     * @param bucket how runs are grouped along the slice's history
     * @param selection which runs take part
     * @param sinceMs only runs recorded at or after this time (ms since the epoch)
     */
    public synchronized List<TrendCell> trendCells(String metric, String slice, TrendBucket bucket,
            Selection selection, long sinceMs) {
        requireTrend(metric, slice);
        if (TrendCells.serves(slice, selection, sinceMs)) {
            return read("aggregate " + metric + " by " + slice, c -> TrendCells.fromAggregates(c, metric, slice,
                    bucket, sinceMs));
        }
        return trendCellsFromRuns(metric, slice, bucket, selection, sinceMs);
    }

    private static void requireTrend(String metric, String slice) {
        StoredMetric.require(metric);
        if (!Selection.COLUMNS.contains(slice)) {
            throw new StoreException(StoreException.Problem.BAD_QUERY, "--by: expected one of robot, site, route, "
                    + "method, version, found \"" + slice + "\"", null);
        }
    }

    /** {@link #trendCells} aggregated from the runs table, whatever the selection (one grouped query). */
    synchronized List<TrendCell> trendCellsFromRuns(String metric, String slice, TrendBucket bucket,
            Selection selection, long sinceMs) {
        requireTrend(metric, slice);
        return read("aggregate " + metric + " by " + slice, c -> TrendCells.fromRuns(c, metric, slice, bucket,
                selection, sinceMs));
    }

    /** Work on the store's connection, for read queries kept beside the concept they serve. */
    @FunctionalInterface
    interface SqlWork<T> {
        T run(Connection c) throws SQLException;
    }

    /**
     * Runs read queries on the store's one connection (synchronized like every method).
     *
     * @param what what is read, for the message of a failure
     */
    synchronized <T> T read(String what, SqlWork<T> work) {
        try {
            return work.run(connection);
        } catch (SQLException e) {
            throw failure("cannot " + what, e);
        }
    }

    static void bindAll(PreparedStatement s, List<Object> args) throws SQLException {
        for (int i = 0; i < args.size(); i++) {
            Object a = args.get(i);
            if (a instanceof Long l) {
                s.setLong(i + 1, l);
            } else {
                s.setString(i + 1, (String) a);
            }
        }
    }

    private StoreException failure(String what, SQLException e) {
        return new StoreException(StoreException.Problem.UNAVAILABLE, location.display() + ": " + what + " ("
                + oneLine(e) + ")", e);
    }

    /** @return the exception's message on one line, without the URL's query */
    static String oneLine(SQLException e) {
        String m = e.getMessage() == null ? e.getClass().getSimpleName() : e.getMessage();
        return m.replaceAll("[\\r\\n]+", " ").strip();
    }

    private void rollbackQuietly() {
        try {
            connection.rollback();
        } catch (SQLException ignored) {
            // the connection is gone; the transaction died with it
        }
    }

    private void autoCommit() {
        try {
            connection.setAutoCommit(true);
        } catch (SQLException ignored) {
            // a broken connection: the next call reports it
        }
    }

    private static void closeQuietly(Connection c) {
        try {
            c.close();
        } catch (SQLException ignored) {
            // closing after a failure: nothing more to report
        }
    }

    /** Closes the connection; SQLite first runs {@code PRAGMA optimize}, as its documentation advises. */
    @Override
    public synchronized void close() {
        if (location.dialect() == Dialect.SQLITE) {
            try (java.sql.Statement s = connection.createStatement()) {
                s.execute("PRAGMA optimize");
            } catch (SQLException ignored) {
                // statistics are an optimisation: a store closing after a failure closes anyway
            }
        }
        closeQuietly(connection);
    }
}
