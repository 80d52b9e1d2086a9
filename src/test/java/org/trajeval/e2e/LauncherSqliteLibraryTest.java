package org.trajeval.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Both installed launchers pass their distribution's SQLite library folder
 * ({@code -Dtrajeval.sqlite.native=$APP_HOME/lib/sqlite-native}): a command that opens the store
 * works with no temp folder at all (the driver's own way copies its library there) and writes no
 * copy into the user's cache; so does reading a rosbag2 sqlite3 bag (core's reader configures the
 * library the same way).
 */
class LauncherSqliteLibraryTest {
    @TempDir
    Path tmp;

    private record Run(int code, String err) {
    }

    /** Runs an installed launcher with no temp folder ({@code -Djava.io.tmpdir} missing) and its own cache. */
    private Run run(String launcher, List<String> args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(launcher));
        cmd.addAll(args);
        Path out = tmp.resolve("out.txt");
        Path err = tmp.resolve("err.txt");
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectOutput(out.toFile()).redirectError(err.toFile());
        pb.environment().put("XDG_CACHE_HOME", tmp.resolve("cache").toString());
        pb.environment().put("JAVA_OPTS", "-Djava.io.tmpdir=" + tmp.resolve("no-such-tmp"));
        pb.environment().remove("TRAJEVAL_OPTS");
        pb.environment().remove("TRAJEVAL_PIPELINE_OPTS");
        Process p = pb.start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the launcher ended");
        return new Run(p.exitValue(), Files.readString(err, StandardCharsets.UTF_8));
    }

    private static String launcher(String launcherProperty) {
        String launcher = System.getProperty(launcherProperty);
        Assumptions.assumeTrue(launcher != null && Files.isExecutable(Paths.get(launcher)),
                "SKIPPED: installed launcher not found (gradle :cli:installDist :pipeline:installDist)");
        return launcher;
    }

    @ParameterizedTest
    @ValueSource(strings = {"trajeval.launcher", "trajeval.pipelineLauncher"})
    void aStoreOpensFromTheInstallsLibraryWithoutTempFolderOrCache(String launcherProperty) throws Exception {
        String launcher = launcher(launcherProperty);
        Path root = Files.createDirectories(tmp.resolve("root"));
        Run r = run(launcher, launcherProperty.equals("trajeval.launcher")
                ? List.of("db", "info", "--db", root.resolve("fleet.db").toString())
                : List.of("watch", "--root", root.toString(), "--drain"));
        assertEquals(0, r.code(), r.err());
        assertFalse(r.err().contains("native"), r.err());
        assertTrue(Files.isRegularFile(root.resolve(launcherProperty.equals("trajeval.launcher") ? "fleet.db"
                : "trajeval.db")), "the store was opened");
        assertFalse(Files.exists(tmp.resolve("cache")), "no copy of the library in the user's cache");
    }

    @Test
    void aRosbag2Sqlite3BagIsReadFromTheInstallsLibraryWithoutTempFolderOrCache() throws Exception {
        String launcher = launcher("trajeval.launcher");
        Path db3 = Paths.get(System.getProperty("trajeval.refdata", "../shared/refdata"), "ros", "tf_example",
                "tf_example.db3").toAbsolutePath();
        assertTrue(Files.isRegularFile(db3), "rosbag2 sqlite3 bag missing: " + db3 + " (../shared/refdata/ros)");
        Run r = run(launcher, List.of("topics", db3.toString()));
        assertEquals(0, r.code(), r.err());
        assertTrue(Files.readString(tmp.resolve("out.txt"), StandardCharsets.UTF_8).contains("/tf"),
                "the bag's topics listed");
        assertFalse(Files.exists(tmp.resolve("cache")), "no copy of the library in the user's cache");
    }
}
