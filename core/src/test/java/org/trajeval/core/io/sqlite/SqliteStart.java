package org.trajeval.core.io.sqlite;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.Statement;
import java.util.Map;

/**
 * A process that opens a SQLite file the way trajeval's store and bag reader do (the library
 * configured first), for the tests that start it in child JVMs: {@code SqliteStart DB [wait]}. It
 * prints the driver's library folder ({@code org.sqlite.lib.path}, "-" when unset) and "open"; with
 * {@code wait} it then keeps the connection open until a line arrives on stdin (or the process is
 * killed). When {@link SqliteNativeLibrary#configure} refuses, it prints the message on stderr and
 * exits 3.
 */
final class SqliteStart {
    private SqliteStart() {
    }

    public static void main(String[] args) throws Exception {
        try {
            SqliteNativeLibrary.configure(System.getenv());
        } catch (IllegalStateException e) {
            System.err.println(e.getMessage());
            System.exit(3);
            return;
        }
        try (Connection c = DriverManager.getConnection("jdbc:sqlite:" + args[0]);
                Statement s = c.createStatement()) {
            s.execute("CREATE TABLE IF NOT EXISTS t (x INTEGER)");
            System.out.println(System.getProperty(SqliteNativeLibrary.LIB_PATH, "-"));
            System.out.println("open");
            System.out.flush();
            if (args.length > 1 && "wait".equals(args[1])) {
                new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8)).readLine();
            }
        }
    }
}
