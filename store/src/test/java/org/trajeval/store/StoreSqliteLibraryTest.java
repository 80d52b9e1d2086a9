package org.trajeval.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.trajeval.core.io.sqlite.NativeLibraryChild.files;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.io.sqlite.NativeLibraryChild;

/**
 * The store configures the SQLite driver's native library (core's {@code SqliteNativeLibrary},
 * tested there) before its first connection: an open or killed store (a child JVM, as users run
 * it) leaves nothing in the temp folder, and when no copy can be loaded it is UNAVAILABLE with
 * the library's one-line message.
 */
class StoreSqliteLibraryTest {
    @TempDir
    Path dir;

    private Process child(Path tmp, Path cache, boolean wait) throws IOException {
        String db = dir.resolve("store.db").toString();
        return NativeLibraryChild.start(tmp, cache, List.of(), StoreStart.class, wait ? List.of(db, "wait") : List.of(db));
    }


    @Test
    void aRunningAndAKilledStoreLeaveNothingInTheTempFolder() throws Exception {
        Path tmp = Files.createDirectories(dir.resolve("tmp"));
        Process p = child(tmp, dir.resolve("cache"), true);
        try {
            BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
            String libPath = out.readLine();
            assertEquals("open", out.readLine(), "the store opened (library folder " + libPath + ")");
            assertTrue(libPath.startsWith(dir.resolve("cache").toString()), libPath);
            assertEquals(List.of(), files(tmp), "nothing in the temp folder while the store is open");
        } finally {
            p.destroyForcibly(); // SIGKILL: no shutdown hook, no deleteOnExit
            assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        }
        assertEquals(List.of(), files(tmp), "nothing in the temp folder after a kill");
    }

    @Test
    void withoutACacheAndATempFolderTheStoreIsUnavailableWithOneLine() throws Exception {
        // /proc cannot hold a new folder, even for root
        Process p = child(dir.resolve("no/such/tmp"), Path.of("/proc/trajeval-no-cache"), false);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the child JVM ended");
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(3, p.exitValue(), "UNAVAILABLE: " + err);
        assertEquals(1, err.strip().lines().count(), err);
        assertTrue(err.startsWith("cannot load SQLite's native library") && err.contains("java.io.tmpdir"), err);
    }
}
