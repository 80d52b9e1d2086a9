package org.trajeval.store;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.time.Clock;
import org.trajeval.core.io.sqlite.SqliteNativeLibrary;

/**
 * A process that opens a SQLite store the way a user's process does, for the tests that start it
 * in child JVMs: {@code StoreStart DB [wait]}. It prints the driver's library folder
 * ({@code org.sqlite.lib.path}, "-" when unset) and "open"; with {@code wait} it then keeps the store
 * open until a line arrives on stdin (or the process is killed). A store that cannot open prints
 * its message on stderr and exits 3 when the store is UNAVAILABLE (4 for any other problem).
 */
final class StoreStart {
    private StoreStart() {
    }

    public static void main(String[] args) throws Exception {
        ResultsStore store;
        try {
            store = ResultsStore.open(StoreLocation.sqlite(Path.of(args[0])), Clock.systemUTC());
        } catch (StoreException e) {
            System.err.println(e.getMessage());
            System.exit(e.problem() == StoreException.Problem.UNAVAILABLE ? 3 : 4);
            return;
        }
        try (store) {
            store.count();
            System.out.println(System.getProperty(SqliteNativeLibrary.LIB_PATH, "-"));
            System.out.println("open");
            System.out.flush();
            if (args.length > 1 && "wait".equals(args[1])) {
                new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8)).readLine();
            }
        }
    }
}
