package org.trajeval.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The installed {@code trajeval-pipeline watch} launcher stopped by a real SIGTERM while it works:
 * it finishes the run in hand, writes nothing half (every report parses, processing/ is empty, no
 * temporary file is left), prints its summary and exits 0 (README, pipeline exit codes); the
 * bundles it had not claimed stay in incoming/.
 */
class PipelineLauncherSignalTest {
    private static final int BUNDLES = 300;
    private static final int POSES = 2000;
    private static final Pattern SUMMARY = Pattern.compile("reported=(\\d+) duplicates=0 failed=0 unfinished=0");

    @TempDir
    Path root;

    @Test
    void sigtermToTheWatchLauncherFinishesTheRunInHandAndExitsZero() throws Exception {
        String launcher = System.getProperty("trajeval.pipelineLauncher");
        assertTrue(launcher != null && Files.isExecutable(Path.of(launcher)),
                "installed launcher missing (gradle :pipeline:installDist): " + launcher);
        Path incoming = Files.createDirectories(root.resolve("incoming"));
        writeBarePairs(incoming);
        Path out = root.resolve("stdout.txt");
        Path err = root.resolve("stderr.txt");
        Process p = new ProcessBuilder(launcher, "watch", "--root", root.toString(), "--no-http", "--workers", "1")
                .redirectOutput(out.toFile()).redirectError(err.toFile()).start();
        Path reports = root.resolve("reports");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(120);
        while (count(reports, ".json") == 0 && System.nanoTime() < deadline && p.isAlive()) {
            Thread.sleep(20);
        }
        assertTrue(p.isAlive(), "the service must be working when SIGTERM comes\n" + Files.readString(err));
        p.destroy(); // SIGTERM to the JVM: the start script exec's java
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the service must stop after SIGTERM");

        String stderr = Files.readString(err, StandardCharsets.UTF_8);
        assertEquals(0, p.exitValue(), "SIGTERM is a normal stop: exit 0, not 143\n" + stderr);
        assertFalse(stderr.contains("\tat "), "no stack trace\n" + stderr);
        Matcher m = SUMMARY.matcher(Files.readString(out, StandardCharsets.UTF_8));
        assertTrue(m.find(), "the summary line is printed: " + Files.readString(out));
        int reported = Integer.parseInt(m.group(1));
        assertTrue(reported > 0 && reported < BUNDLES, "SIGTERM must land mid-work: " + reported + " reported");
        assertEquals(reported, count(reports, ".json"), "one complete report file per run reported");
        try (Stream<Path> s = Files.list(reports)) {
            for (Path r : s.toList()) {
                assertFalse(r.getFileName().toString().startsWith("."), "temporary file left: " + r);
                JsonNode report = new ObjectMapper().readTree(r.toFile()); // a half-written file fails here
                assertTrue(report.at("/evaluation/ate/trans_m/rmse").isNumber(), r.toString());
            }
        }
        assertEquals(0, count(root.resolve("processing"), ""), "nothing left half-done in processing/");
        assertEquals(reported, count(root.resolve("done"), ""), "every claimed bundle finished");
        assertEquals(3L * (BUNDLES - reported), count(incoming, ""), "unclaimed bundles stay in incoming/");
    }

    /** Bare pairs run-N.gt.csv + run-N.est.csv + run-N.done: a circle, the estimate 0.1 m off in x. */
    private static void writeBarePairs(Path incoming) throws IOException {
        StringBuilder gt = new StringBuilder("t,x,y,yaw\n");
        StringBuilder est = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i < POSES; i++) {
            double t = 0.1 * i;
            double a = 0.01 * i;
            gt.append(String.format(Locale.ROOT, "%.1f,%.6f,%.6f,%.6f%n", t, 10 * Math.cos(a), 10 * Math.sin(a), a));
            est.append(String.format(Locale.ROOT, "%.1f,%.6f,%.6f,%.6f%n", t, 10 * Math.cos(a) + 0.1, 10 * Math.sin(a), a));
        }
        byte[] g = gt.toString().getBytes(StandardCharsets.UTF_8);
        byte[] e = est.toString().getBytes(StandardCharsets.UTF_8);
        for (int n = 0; n < BUNDLES; n++) {
            Files.write(incoming.resolve("run-" + n + ".gt.csv"), g);
            Files.write(incoming.resolve("run-" + n + ".est.csv"), e);
            Files.write(incoming.resolve("run-" + n + ".done"), new byte[0]);
        }
    }

    private static long count(Path dir, String suffix) throws IOException {
        if (!Files.isDirectory(dir)) {
            return 0;
        }
        try (Stream<Path> s = Files.list(dir)) {
            return s.filter(x -> x.getFileName().toString().endsWith(suffix)).count();
        }
    }
}
