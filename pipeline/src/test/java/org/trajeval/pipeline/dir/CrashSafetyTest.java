package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.PipelineCommand;
import org.trajeval.pipeline.ledger.Ledger;
import org.trajeval.pipeline.ledger.LedgerEntry;

/**
 * The service, as a child JVM, is killed with SIGKILL at seeded random times while it works on 100
 * bundles, restarted, killed again, ...; a final {@code watch --drain} finishes. In the end every
 * run has exactly one report, every report parses, and nothing is left in incoming/ or processing/
 * (a kill between a claim's mkdir and its rename leaves an empty {@code .claim-*} folder, which a start
 * removes once it is 60 s old: the test ages such folders and checks that one more start removes them).
 */
class CrashSafetyTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final int BUNDLES = 100;
    private static final int KILLS = 6;
    /** Poses per run: enough work per bundle that kills land while runs are in flight. */
    private static final int POSES = 2000;

    @TempDir
    Path root;

    private Process start(List<String> jvmArgs, String... args) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-Xmx256m");
        cmd.add("-XX:TieredStopAtLevel=1");
        cmd.addAll(jvmArgs);
        cmd.add("-cp");
        cmd.add(System.getProperty("trajeval.testClasspath", System.getProperty("java.class.path")));
        cmd.add(PipelineCommand.class.getName());
        cmd.addAll(List.of(args));
        return new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(root.resolve("child.log").toFile())).start();
    }

    @Test
    void killedAndRestartedRepeatedlyEveryRunEndsWithExactlyOneCompleteReport() throws Exception {
        DirectoryLayout layout = new DirectoryLayout(root.resolve("svc")).create();
        for (int i = 0; i < BUNDLES; i++) {
            String runId = "run-" + i;
            switch (i % 3) {
                case 0 -> Fixtures.folderBundle(layout.incoming(), "b-" + i, runId, POSES, i);
                case 1 -> Fixtures.zipBundle(layout.incoming(), "b-" + i, runId, POSES, i);
                default -> Fixtures.pair(layout.incoming(), runId, POSES, i);
            }
            Fixtures.marker(layout.incoming(), i % 3 == 2 ? runId : "b-" + i);
        }
        Random rnd = new Random(7321L);
        String svc = layout.root().toString();
        List<Integer> progress = new ArrayList<>();
        for (int k = 0; k < KILLS; k++) {
            Process p = start(List.of(), "watch", "--root", svc, "--no-http", "--workers", "2");
            // kill at a random moment once this instance is at work (its first new report), so that
            // a fast, quiet machine cannot finish everything before the first kill
            int before = list(layout.reports()).size();
            long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
            while (list(layout.reports()).size() == before && p.isAlive() && System.nanoTime() < deadline) {
                Thread.sleep(5);
            }
            Thread.sleep(rnd.nextInt(250));
            p.destroyForcibly();
            assertTrue(p.waitFor(30, TimeUnit.SECONDS));
            progress.add(list(layout.done()).size());
        }
        System.err.println("CrashSafetyTest: bundles done after each SIGKILL: " + progress);
        // the kills must have hit a service at work, or the test would prove nothing
        assertTrue(progress.get(0) < BUNDLES, "the first kill came after all the work: " + progress);
        Path classLog = root.resolve("classes.log");
        Process last = start(List.of("-Xlog:class+load=info:file=" + classLog), "watch", "--root", svc, "--drain",
                "--workers", "2");
        assertTrue(last.waitFor(180, TimeUnit.SECONDS), "the final drain must finish");
        assertEquals(0, last.exitValue(), () -> log());

        Map<String, Integer> reports = new HashMap<>();
        try (Stream<Path> s = Files.list(layout.reports())) {
            for (Path p : s.filter(p -> !p.getFileName().toString().startsWith(".")).collect(Collectors.toList())) {
                JsonNode r = JSON.readTree(p.toFile()); // throws on a truncated file
                assertEquals(p.getFileName().toString(), r.get("run_id").asText() + ".json");
                assertTrue(r.get("evaluation").get("ate").get("trans_m").get("rmse").isNumber());
                reports.merge(r.get("run_id").asText(), 1, Integer::sum);
            }
        }
        assertEquals(BUNDLES, reports.size(), "one report per run");
        assertTrue(reports.values().stream().allMatch(n -> n == 1));
        try (Ledger ledger = Ledger.open(layout.ledger())) {
            ledger.locked(v -> null);
            List<LedgerEntry> entries = ledger.entries();
            assertEquals(BUNDLES, entries.stream().map(LedgerEntry::runId).distinct().count());
            assertTrue(entries.stream().allMatch(e -> e.version() == 1), "no run may get a second version");
        }
        assertEquals(0, list(layout.incoming()).size());
        assertOnlyRecentDeadClaims(layout.processing());
        assertEquals(List.of(), list(layout.failed()));
        // the directory mode runs without any Kafka class
        assertFalse(Files.readString(classLog).contains("org.apache.kafka"), "Kafka classes were loaded");
    }

    /**
     * A kill between a claim's mkdir and its rename leaves {@code processing/.claim-ID/} empty or holding
     * only its (free) lock file; a start within 60 s of it leaves it alone, since a live instance may be
     * between creating and locking that file ({@code Slot.resume}). Anything else in processing/ is a
     * lost or stuck bundle. The leftovers are then aged past 60 s, and one more start must remove them.
     */
    private void assertOnlyRecentDeadClaims(Path processing) throws Exception {
        List<String> left = list(processing);
        for (String name : left) {
            assertTrue(name.startsWith(".claim-"), () -> "a bundle was left in processing/: " + left);
            Path dir = processing.resolve(name);
            List<String> inside = list(dir);
            // killed after its mkdir: empty; after creating its lock file: that file alone
            assertTrue(inside.isEmpty() || inside.equals(List.of(Slot.LOCK)),
                    () -> "a claim folder holds more than its lock: " + name + " " + inside);
            long ageMs = System.currentTimeMillis() - Files.getLastModifiedTime(dir).toMillis();
            assertTrue(ageMs < 60_000, "a dead claim older than 60 s survived a start: " + name);
            Files.setLastModifiedTime(dir, java.nio.file.attribute.FileTime.fromMillis(
                    System.currentTimeMillis() - 61_000));
        }
        if (!left.isEmpty()) {
            System.err.println("CrashSafetyTest: claims killed before their rename: " + left);
            Process again = start(List.of(), "watch", "--root", processing.getParent().toString(), "--drain",
                    "--workers", "2");
            assertTrue(again.waitFor(120, TimeUnit.SECONDS), "the drain after ageing the claims must finish");
            assertEquals(0, again.exitValue(), () -> log());
        }
        assertEquals(List.of(), list(processing));
    }

    private static List<String> list(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).collect(Collectors.toList());
        }
    }

    private String log() {
        try {
            return Files.readString(root.resolve("child.log"));
        } catch (IOException e) {
            return e.toString();
        }
    }

}
