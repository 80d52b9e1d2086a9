package org.trajeval.store;

import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;

/**
 * Switches a SQLite connection's file to WAL mode, waiting for other connections' locks.
 *
 * <p>The switch needs the file to itself, and SQLite answers it with {@code SQLITE_BUSY} at once,
 * without its busy handler, while another connection holds a lock. Two processes opening a fresh
 * store at the same moment (a pipeline and a CLI, two pipeline replicas) would then see one of
 * them fail; here the switch is tried again every {@value #RETRY_MS} ms for up to the store's busy
 * timeout, like any other write. A file already in WAL mode answers at once.
 */
final class SqliteWal {
    /** How long any SQLite statement of the store waits for another connection's lock, in ms. */
    static final int BUSY_TIMEOUT_MS = 30_000;
    static final int RETRY_MS = 10;
    private static final int SQLITE_BUSY = 5;
    private static final int SQLITE_LOCKED = 6;

    private SqliteWal() {
    }

    /**
     * @throws SQLException when the file stays locked longer than {@link #BUSY_TIMEOUT_MS} or
     *     refuses WAL mode (a file system without shared memory answers with another mode)
     */
    static void enable(Connection c) throws SQLException {
        long deadline = System.nanoTime() + BUSY_TIMEOUT_MS * 1_000_000L;
        while (true) {
            try (Statement s = c.createStatement(); ResultSet rs = s.executeQuery("PRAGMA journal_mode=WAL")) {
                String mode = rs.next() ? rs.getString(1) : "";
                if (!"wal".equalsIgnoreCase(mode)) {
                    throw new SQLException("the file refused WAL mode and stayed in mode '" + mode + "'");
                }
                return;
            } catch (SQLException e) {
                int code = e.getErrorCode();
                boolean locked = code == SQLITE_BUSY || code == SQLITE_LOCKED;
                if (!locked || System.nanoTime() > deadline) {
                    throw e;
                }
            }
            try {
                Thread.sleep(RETRY_MS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new SQLException("interrupted while waiting for the file's lock", e);
            }
        }
    }
}
