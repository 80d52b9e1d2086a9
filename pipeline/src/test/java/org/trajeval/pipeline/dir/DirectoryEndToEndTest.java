package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.HashSet;
import java.util.Random;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.TestScorers;
import org.trajeval.pipeline.bundle.BundleLimits;

/**
 * 200 bundles dropped while the service runs: folders, zips and bare pairs, some written in two
 * steps (half-written, then completed), some malformed, some re-sent duplicates. Exactly one report
 * per good run, every bad one in failed/ with its reason, nothing left in incoming/.
 */
class DirectoryEndToEndTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final int BUNDLES = 200;
    private static final int POSES = 200;

    @TempDir
    Path root;

    @Test
    void twoHundredBundlesDroppedWhileRunningGiveOneReportPerGoodRun() throws Exception {
        Set<String> good = new HashSet<>();
        Set<String> bad = new HashSet<>();
        int duplicates = 0;
        try (ServiceHarness h = new ServiceHarness(root, TestScorers.real(),
                new DirectoryOptions(2, 2, Completion.MARKER, Duration.ofSeconds(60), Duration.ofMillis(20)),
                BundleLimits.DEFAULTS)) {
            ExecutorService bg = Executors.newSingleThreadExecutor();
            Future<DrainSummary> running = bg.submit(h.service::runUntilStopped);
            Path in = h.layout.incoming();
            Random rnd = new Random(20240601L);
            int originals = 0;
            for (int i = 0; i < BUNDLES; i++) {
                boolean duplicate = i % 10 == 9; // re-send an earlier folder or zip run under a new bundle name
                if (duplicate) {
                    int of = (i - 6) % 3 != 2 ? i - 6 : i - 5; // never a bare pair: its metadata differs

                    String runId = "run-" + of;
                    Fixtures.folderBundle(in, "dup-" + i, runId, POSES, of);
                    Fixtures.marker(in, "dup-" + i);
                    duplicates++;
                    continue;
                }
                originals++;
                String runId = "run-" + i;
                boolean malformed = i % 10 == 7;
                boolean halfWritten = i % 10 == 2;
                switch (i % 3) {
                    case 0 -> {
                        Path b = Fixtures.folderBundle(in, "b-" + i, runId, POSES, i);
                        if (malformed) {
                            Files.writeString(b.resolve("est.csv"), "t,x,y,yaw\n0,0,0,0\n0.1,oops,0,0\n");
                        }
                        if (halfWritten) {
                            // the estimate is still being exported: cut, then completed before the marker
                            String full = Files.readString(b.resolve("est.csv"));
                            Files.writeString(b.resolve("est.csv"), full.substring(0, full.length() / 3));
                            Thread.sleep(30);
                            Files.writeString(b.resolve("est.csv"), full);
                        }
                        Fixtures.marker(in, "b-" + i);
                        if (malformed) {
                            bad.add("b-" + i);
                        }
                    }
                    case 1 -> {
                        if (malformed) {
                            Fixtures.write(in.resolve("b-" + i + ".zip"), "this is not a zip archive");
                            bad.add("b-" + i + ".zip");
                        } else {
                            Fixtures.zipBundle(in, "b-" + i, runId, POSES, i);
                        }
                        Fixtures.marker(in, "b-" + i);
                    }
                    default -> {
                        Fixtures.pair(in, runId, POSES, i);
                        if (malformed) {
                            Files.writeString(in.resolve(runId + ".gt.csv"), "t,x,y\n0,0,0\n");
                            bad.add(runId + ".pair");
                        }
                        if (halfWritten) {
                            Files.delete(in.resolve(runId + ".est.csv"));
                            Thread.sleep(30);
                            Fixtures.writeTrajectory(in.resolve(runId + ".est.csv"), POSES, 0.05, i + 1000);
                        }
                        Fixtures.marker(in, runId);
                    }
                }
                if (!malformed) {
                    good.add(runId);
                }
                if (rnd.nextInt(4) == 0) {
                    Thread.sleep(5);
                }
            }
            assertEquals(BUNDLES, originals + duplicates);
            long deadline = System.nanoTime() + Duration.ofMinutes(3).toNanos();
            while (System.nanoTime() < deadline
                    && (count(in) > 0 || count(h.layout.processing()) > 0
                            || count(h.layout.done()) + errorFiles(h.layout.failed()) < BUNDLES)) {
                Thread.sleep(100);
            }
            h.service.stop();
            DrainSummary s = running.get();
            bg.shutdown();

            assertEquals(0, count(in), "nothing may stay in incoming/");
            assertEquals(0, count(h.layout.processing()));
            Set<String> reports;
            try (Stream<Path> r = Files.list(h.layout.reports())) {
                reports = r.map(p -> p.getFileName().toString()).collect(Collectors.toSet());
            }
            assertEquals(good.stream().map(id -> id + ".json").collect(Collectors.toSet()), reports,
                    "exactly one report per good run");
            for (String id : good) {
                JsonNode rep = JSON.readTree(h.layout.reports().resolve(id + ".json").toFile());
                assertEquals(id, rep.get("run_id").asText());
                assertEquals(1, rep.get("run_version").asInt());
                assertTrue(rep.get("evaluation").get("ate").get("trans_m").get("rmse").isNumber());
            }
            for (String b : bad) {
                JsonNode err = JSON.readTree(h.layout.failed().resolve(b + ".error.json").toFile());
                assertTrue(!err.get("message").asText().isBlank() && err.hasNonNull("stage"), err.toString());
            }
            assertEquals(bad.size(), errorFiles(h.layout.failed()));
            assertEquals(new DrainSummary(good.size(), duplicates, bad.size()), s);
            assertEquals(good.size(), h.ledger.entries().size());
        }
    }

    private static long count(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.count();
        }
    }

    private static long errorFiles(Path failed) throws IOException {
        try (Stream<Path> s = Files.list(failed)) {
            return s.filter(p -> p.getFileName().toString().endsWith(".error.json")).count();
        }
    }
}
