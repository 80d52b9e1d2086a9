package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.PipelineCommand;

/**
 * SIGTERM while the service works: in-flight runs finish, the process exits 0 with its summary
 * line, nothing is left half-done in processing/, every report written is complete, and the bundles not yet claimed stay in
 * incoming/ for the next start, which reports them.
 */
class GracefulShutdownTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final int BUNDLES = 100;

    @TempDir
    Path root;

    private Process start(String... args) throws IOException {
        List<String> cmd = new ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.add("-Xmx256m");
        cmd.add("-XX:TieredStopAtLevel=1");
        cmd.add("-cp");
        cmd.add(System.getProperty("trajeval.testClasspath", System.getProperty("java.class.path")));
        cmd.add(PipelineCommand.class.getName());
        cmd.addAll(List.of(args));
        return new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(root.resolve("child.log").toFile())).start();
    }

    @Test
    void sigtermLetsInFlightRunsFinishAndLosesNothing() throws Exception {
        DirectoryLayout layout = new DirectoryLayout(root.resolve("svc")).create();
        for (int i = 0; i < BUNDLES; i++) {
            // 3000-pose runs keep the workers busy long enough for SIGTERM to land mid-work
            Fixtures.pair(layout.incoming(), "run-" + i, 3000, i);
            Fixtures.marker(layout.incoming(), "run-" + i);
        }
        String svc = layout.root().toString();
        Process p = start("watch", "--root", svc, "--no-http", "--workers", "2");
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (list(layout.reports()).isEmpty() && System.nanoTime() < deadline) {
            Thread.sleep(50);
        }
        assertTrue(p.isAlive(), "the service must still be running when SIGTERM comes");
        p.destroy(); // SIGTERM
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the service must stop after SIGTERM");
        assertEquals(0, p.exitValue(), () -> "SIGTERM is a normal stop: exit 0\n" + read(root.resolve("child.log")));
        assertTrue(read(root.resolve("child.log")).contains("reported="), "the summary line is printed on SIGTERM too");
        int reportedAtStop = reports(layout).size();
        assertTrue(reportedAtStop < BUNDLES, "SIGTERM came after all the work: " + reportedAtStop);
        assertEquals(List.of(), list(layout.processing()), "nothing left half-done in processing/");
        assertEquals(reportedAtStop, list(layout.done()).size(), "every claimed bundle finished");

        Process drain = start("watch", "--root", svc, "--drain", "--workers", "2");
        assertTrue(drain.waitFor(180, TimeUnit.SECONDS));
        assertEquals(0, drain.exitValue(), () -> read(root.resolve("child.log")));
        assertEquals(BUNDLES, reports(layout).size(), "every run reported once in the end");
        assertEquals(List.of(), list(layout.incoming()));
    }

    /** @return the run ids of the reports, each parsed completely (a truncated file fails here) */
    private static List<String> reports(DirectoryLayout layout) throws IOException {
        List<String> ids = new ArrayList<>();
        for (String name : list(layout.reports())) {
            if (name.startsWith(".")) {
                continue;
            }
            JsonNode r = JSON.readTree(layout.reports().resolve(name).toFile());
            assertTrue(r.get("evaluation").get("ate").get("trans_m").get("rmse").isNumber());
            ids.add(r.get("run_id").asText());
        }
        return ids;
    }

    private static List<String> list(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(x -> x.getFileName().toString()).collect(Collectors.toList());
        }
    }

    private static String read(Path p) {
        try {
            return Files.readString(p);
        } catch (IOException e) {
            return e.toString();
        }
    }
}
