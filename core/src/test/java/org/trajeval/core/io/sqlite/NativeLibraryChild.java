package org.trajeval.core.io.sqlite;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;

/**
 * A child JVM on the test's class path with a temp folder and a user cache of its own, the way a
 * user's process meets SQLite's native library: for the tests that count the copies it leaves
 * ({@code SqliteNativeLibraryTest}, the bag reader's and the store's). Test sources only.
 */
public final class NativeLibraryChild {
    private NativeLibraryChild() {
    }

    /**
     * Starts {@code main} with {@code -Djava.io.tmpdir=tmp}, {@code XDG_CACHE_HOME=cache} and no
     * JVM options from the environment.
     *
     * @param jvmOptions options before the class path (e.g. {@code -Dorg.sqlite.lib.path=...})
     * @param args the main class's arguments
     */
    public static Process start(Path tmp, Path cache, List<String> jvmOptions, Class<?> main, List<String> args)
            throws IOException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xshare:auto", "-XX:TieredStopAtLevel=1", "-Djava.io.tmpdir=" + tmp));
        cmd.addAll(jvmOptions);
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), main.getName()));
        cmd.addAll(args);
        ProcessBuilder pb = new ProcessBuilder(cmd);
        pb.environment().put("XDG_CACHE_HOME", cache.toString());
        pb.environment().remove("JAVA_TOOL_OPTIONS");
        pb.environment().remove("_JAVA_OPTIONS");
        return pb.start();
    }

    /** @return the regular files under {@code root}, none when it does not exist */
    public static List<Path> files(Path root) throws IOException {
        if (!Files.exists(root)) {
            return List.of();
        }
        try (Stream<Path> s = Files.walk(root)) {
            return s.filter(Files::isRegularFile).toList();
        }
    }
}
