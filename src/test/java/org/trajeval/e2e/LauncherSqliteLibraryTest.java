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
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Both installed launchers pass their distribution's SQLite library folder
 * ({@code -Dtrajeval.sqlite.native=$APP_HOME/lib/sqlite-native}): a command that opens the store
 * works with no temp folder at all (the driver's own way copies its library there) and writes no
 * copy into the user's cache.
 */
class LauncherSqliteLibraryTest {
    @TempDir
    Path tmp;

    @ParameterizedTest
    @ValueSource(strings = {"trajeval.launcher", "trajeval.pipelineLauncher"})
    void aStoreOpensFromTheInstallsLibraryWithoutTempFolderOrCache(String launcherProperty) throws Exception {
        String launcher = System.getProperty(launcherProperty);
        Assumptions.assumeTrue(launcher != null && Files.isExecutable(Paths.get(launcher)),
                "SKIPPED: installed launcher not found (gradle :cli:installDist :pipeline:installDist)");
        Path root = Files.createDirectories(tmp.resolve("root"));
        List<String> cmd = new ArrayList<>(List.of(launcher));
        cmd.addAll(launcherProperty.equals("trajeval.launcher")
                ? List.of("db", "info", "--db", root.resolve("fleet.db").toString())
                : List.of("watch", "--root", root.toString(), "--drain"));
        Path out = tmp.resolve("out.txt");
        Path err = tmp.resolve("err.txt");
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectOutput(out.toFile()).redirectError(err.toFile());
        Path cache = tmp.resolve("cache");
        pb.environment().put("XDG_CACHE_HOME", cache.toString());
        pb.environment().put("JAVA_OPTS", "-Djava.io.tmpdir=" + tmp.resolve("no-such-tmp"));
        pb.environment().remove("TRAJEVAL_OPTS");
        pb.environment().remove("TRAJEVAL_PIPELINE_OPTS");
        Process p = pb.start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "the launcher ended");
        String errText = Files.readString(err, StandardCharsets.UTF_8);
        assertEquals(0, p.exitValue(), errText);
        assertFalse(errText.contains("native"), errText);
        assertTrue(Files.isRegularFile(root.resolve(launcherProperty.equals("trajeval.launcher") ? "fleet.db"
                : "trajeval.db")), "the store was opened");
        assertFalse(Files.exists(cache), "no copy of the library in the user's cache");
    }
}
