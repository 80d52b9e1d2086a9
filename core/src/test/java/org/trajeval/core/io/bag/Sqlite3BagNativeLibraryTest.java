package org.trajeval.core.io.bag;

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
 * Reading a rosbag2 sqlite3 bag ({@code ../shared/refdata/ros/tf_example/tf_example.db3}) in a
 * child JVM, as {@code trajeval eval} does, loads SQLite's native library from the fixed copy
 * (core's {@code SqliteNativeLibrary}): nothing is written into the temp folder while it runs or
 * after it is killed (the driver's own way leaves a 1.1 MB copy and its lock there), and when no
 * copy can be loaded the bag is refused with one line naming the file.
 */
class Sqlite3BagNativeLibraryTest {
    private static final String TOPIC = "/tf:odom.base_link";

    @TempDir
    Path dir;

    private static Path bag() {
        Path db3 = BagEvoParityTest.rosData().resolve("tf_example/tf_example.db3").toAbsolutePath();
        assertTrue(Files.isRegularFile(db3), "rosbag2 sqlite3 bag missing: " + db3);
        return db3;
    }

    private Process child(Path tmp, Path cache, boolean wait) throws IOException {
        List<String> args = wait ? List.of(bag().toString(), TOPIC, "wait") : List.of(bag().toString(), TOPIC);
        return NativeLibraryChild.start(tmp, cache, List.of(), BagStart.class, args);
    }


    @Test
    void readingASqlite3BagLeavesNothingInTheTempFolderEvenWhenKilled() throws Exception {
        Path tmp = Files.createDirectories(dir.resolve("tmp"));
        Process p = child(tmp, dir.resolve("cache"), true);
        try {
            BufferedReader out = new BufferedReader(new InputStreamReader(p.getInputStream(), StandardCharsets.UTF_8));
            String poses = out.readLine();
            // README of refdata/ros: 517 /tf messages with odom->base_footprint (RealBagsTest reads the same)
            assertEquals("517", poses, "poses read from the bag");
            assertEquals("read", out.readLine());
            assertEquals(List.of(), files(tmp), "nothing in the temp folder while the reader's JVM runs");
        } finally {
            p.destroyForcibly(); // SIGKILL: no shutdown hook, no deleteOnExit
            assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        }
        assertEquals(List.of(), files(tmp), "nothing in the temp folder after a kill");
        assertEquals(1, files(dir.resolve("cache")).size(), "one copy of the library in the cache");
    }

    @Test
    void withoutACacheAndATempFolderTheBagIsRefusedWithOneLineNamingIt() throws Exception {
        // /proc cannot hold a new folder, even for root
        Process p = child(dir.resolve("no/such/tmp"), Path.of("/proc/trajeval-no-cache"), false);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the child JVM ended");
        String err = new String(p.getErrorStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(2, p.exitValue(), err);
        assertEquals(1, err.strip().lines().count(), err);
        assertTrue(err.startsWith(bag() + ": cannot load SQLite's native library") && err.contains("java.io.tmpdir"),
                err);
    }
}
