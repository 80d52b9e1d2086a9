package org.trajeval.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.nio.file.StandardCopyOption;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.EnumSource;

/**
 * The installed launcher's Class-Data Sharing archive ({@code lib/trajeval.jsa}, written by the
 * build's {@code :cli:cdsArchive} training run): the real install uses it, and an install whose
 * archive is unusable (moved install, garbage, truncated, missing) still runs with the same output
 * and nothing on stderr or stdout from the JVM.
 */
class StartupArchiveTest {
    private static final String ARCHIVE = "trajeval.jsa";

    @TempDir
    static Path tmp;
    private static Path launcher;
    private static Path ref;
    private static Path est;

    record Result(int code, String out, String err) {
    }

    @BeforeAll
    static void installedLauncherAndASmallPlanarPair() throws IOException {
        String l = System.getProperty("trajeval.launcher");
        Assumptions.assumeTrue(l != null && Files.isExecutable(Paths.get(l)),
                "SKIPPED: installed launcher not found (gradle :cli:installDist)");
        launcher = Paths.get(l);
        // seeded pair: reference on a curve, estimate 3 ms later, offset and noisy
        Random rnd = new Random(11);
        StringBuilder r = new StringBuilder("t,x,y,yaw\n");
        StringBuilder e = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i < 500; i++) {
            double t = 10.0 + 0.1 * i;
            double x = 0.4 * i;
            double y = 3.0 * Math.sin(0.02 * i);
            double yaw = 0.1 * Math.cos(0.02 * i);
            r.append(String.format(Locale.ROOT, "%.2f,%.6f,%.6f,%.9f%n", t, x, y, yaw));
            e.append(String.format(Locale.ROOT, "%.6f,%.6f,%.6f,%.9f%n", t + 0.003,
                    x + 1.0 + 0.02 * rnd.nextGaussian(), y - 0.5 + 0.02 * rnd.nextGaussian(), yaw + 0.05));
        }
        ref = Files.writeString(tmp.resolve("ref.csv"), r);
        est = Files.writeString(tmp.resolve("est.csv"), e);
    }

    private static Result launch(Path script, Map<String, String> env, String... args)
            throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>();
        cmd.add(script.toString());
        cmd.addAll(List.of(args));
        Path out = Files.createTempFile(tmp, "out", ".txt");
        Path err = Files.createTempFile(tmp, "err", ".txt");
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(tmp.toFile())
                .redirectOutput(out.toFile()).redirectError(err.toFile());
        pb.environment().remove("JAVA_OPTS");
        pb.environment().remove("TRAJEVAL_OPTS");
        pb.environment().remove("TRAJEVAL_CDS");
        pb.environment().putAll(env);
        Process p = pb.start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "launcher did not finish");
        return new Result(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8),
                Files.readString(err, StandardCharsets.UTF_8));
    }

    private static String[] evalArgs() {
        return new String[] {"eval", ref.toString(), est.toString(), "--threads", "1", "--convention", "lesson",
            "--association", "interpolate", "--align", "se2", "--rpe-delta", "1", "--rpe-unit", "s", "--json"};
    }

    /** The JSON the launcher prints with the archive switched off: what every variant must print. */
    private static String reportWithoutArchive() throws Exception {
        Result r = launch(launcher, Map.of("TRAJEVAL_CDS", "off"), evalArgs());
        assertEquals(0, r.code(), r.err());
        return r.out();
    }

    @Test
    void buildWroteACompleteArchiveIntoTheInstall() throws IOException {
        Path lib = launcher.getParent().resolveSibling("lib");
        Path jsa = lib.resolve(ARCHIVE);
        assertTrue(Files.isRegularFile(jsa), "the build's cdsArchive task writes " + jsa);
        long expected = Long.parseLong(Files.readString(lib.resolve(ARCHIVE + ".bytes")).strip());
        assertEquals(expected, Files.size(jsa));
    }

    @Test
    void installedLauncherMapsItsArchive() throws Exception {
        // -Xshare:on makes the JVM refuse to start when it cannot map the archive
        Result r = launch(launcher, Map.of("TRAJEVAL_OPTS", "-Xshare:on"), "--version");
        assertEquals(0, r.code(), r.out() + r.err());
        assertEquals("", r.err());
        assertTrue(r.out().startsWith("trajeval "), r.out());
    }

    @Test
    void installedLauncherWithTheArchiveEvaluatesLikeWithoutItAndPrintsNothingOnStderr() throws Exception {
        Result r = launch(launcher, Map.of(), evalArgs());
        assertEquals(0, r.code(), r.err());
        assertEquals("", r.err(), "no JVM note on stderr");
        assertEquals(reportWithoutArchive(), r.out());
        assertEquals("trajeval.evaluation", new ObjectMapper().readTree(r.out()).at("/schema").asText());
    }

    /** What happened to the archive of a copy of the install. */
    enum Damage {
        /** the archive made for the original install: its jar paths no longer match. */
        MOVED_INSTALL,
        /** random bytes, as many as the archive had (passes the launcher's size check). */
        GARBAGE_OF_THE_SAME_SIZE,
        /** the first half only (a JVM mapping it would crash with SIGBUS). */
        TRUNCATED,
        /** deleted. */
        MISSING
    }

    @ParameterizedTest
    @EnumSource(Damage.class)
    void unusableArchiveIsIgnoredSilently(Damage damage) throws Exception {
        Path copy = copyOfTheInstall(tmp.resolve("install " + damage));
        Path jsa = copy.resolve("lib").resolve(ARCHIVE);
        long size = Files.size(jsa);
        switch (damage) {
            case MOVED_INSTALL -> { }
            case GARBAGE_OF_THE_SAME_SIZE -> {
                byte[] junk = new byte[(int) size];
                new Random(3).nextBytes(junk);
                Files.write(jsa, junk);
            }
            case TRUNCATED -> {
                byte[] head = new byte[(int) (size / 2)];
                System.arraycopy(Files.readAllBytes(jsa), 0, head, 0, head.length);
                Files.write(jsa, head);
            }
            case MISSING -> Files.delete(jsa);
            default -> throw new AssertionError(damage);
        }
        Path script = copy.resolve("bin").resolve("trajeval");
        Result version = launch(script, Map.of(), "--version");
        assertEquals(0, version.code(), version.out() + version.err());
        assertEquals("", version.err());
        assertEquals(launch(launcher, Map.of("TRAJEVAL_CDS", "off"), "--version").out(), version.out(),
                "no JVM note on stdout either");

        Result eval = launch(script, Map.of(), evalArgs());
        assertEquals(0, eval.code(), eval.err());
        assertEquals("", eval.err());
        assertEquals(reportWithoutArchive(), eval.out());
        try (Stream<Path> files = Files.list(tmp)) {
            assertFalse(files.anyMatch(f -> f.getFileName().toString().startsWith("hs_err")), "JVM crash log");
        }
    }

    /** Copies the installed distribution (bin, lib) into {@code target}, keeping the scripts executable. */
    private static Path copyOfTheInstall(Path target) throws IOException {
        Path home = launcher.getParent().getParent();
        try (Stream<Path> files = Files.walk(home)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Path to = target.resolve(home.relativize(f).toString());
                if (Files.isDirectory(f)) {
                    Files.createDirectories(to);
                } else {
                    Files.copy(f, to, StandardCopyOption.COPY_ATTRIBUTES);
                    to.toFile().setWritable(true, true);
                }
            }
        }
        return target;
    }
}
