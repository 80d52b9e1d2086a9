package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.nio.file.attribute.PosixFilePermissions;
import java.time.Duration;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.Version;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.StandInScorer;
import org.trajeval.pipeline.bundle.BundleLimits;
import org.trajeval.pipeline.bundle.ContentHash;

class DirectoryServiceTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path root;

    private static long count(Path dir, String suffix) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.filter(p -> p.getFileName().toString().endsWith(suffix)).count();
        }
    }

    @Test
    void folderZipAndPairBundlesEachGetOneReportAndMoveToDone() throws IOException {
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            Path in = h.layout.incoming();
            Fixtures.folderBundle(in, "b1", "run-1", 50, 1);
            Fixtures.marker(in, "b1");
            Fixtures.zipBundle(in, "b2", "run-2", 50, 2);
            Fixtures.marker(in, "b2");
            Fixtures.pair(in, "run-3", 50, 3);
            Fixtures.marker(in, "run-3");
            DrainSummary s = h.service.drain();
            assertEquals(new DrainSummary(3, 0, 0), s);
            assertEquals(0, s.exitCode());
            for (String id : new String[] {"run-1", "run-2", "run-3"}) {
                assertTrue(Files.exists(h.layout.reports().resolve(id + ".json")), id);
            }
            assertEquals(0, count(in, ""));
            assertEquals(0, count(h.layout.processing(), ""));
            assertTrue(Files.isDirectory(h.layout.done().resolve("b1")));
            assertTrue(Files.isDirectory(h.layout.done().resolve("b2.zip")));
            assertTrue(Files.isDirectory(h.layout.done().resolve("run-3.pair")));
        }
    }

    @Test
    void reportHoldsRunMetadataInputHashesToolVersionAndIsWorldReadable() throws IOException {
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            Path b = Fixtures.folderBundle(h.layout.incoming(), "b1", "run-1", 50, 1);
            String gtHash = ContentHash.ofFile(b.resolve("gt.csv"));
            Fixtures.marker(h.layout.incoming(), "b1");
            h.service.drain();
            Path report = h.layout.reports().resolve("run-1.json");
            JsonNode r = JSON.readTree(report.toFile());
            assertEquals("trajeval.pipeline.run", r.get("schema").asText());
            assertEquals(Version.TOOL, r.get("tool_version").asText());
            assertEquals("run-1", r.get("run_id").asText());
            assertEquals("bot-1", r.get("robot_id").asText());
            assertEquals(1, r.get("seed").asLong());
            assertEquals(1, r.get("run_version").asInt());
            assertEquals(gtHash, r.get("reference_sha256").asText());
            assertEquals("trajeval.evaluation", r.get("evaluation").get("schema").asText());
            assertEquals(PosixFilePermissions.fromString("rw-r--r--"), Files.getPosixFilePermissions(report));
        }
    }

    @Test
    void identicalResentRunIsRecognisedAndAChangedOneBecomesVersionTwo() throws IOException {
        Path in;
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            in = h.layout.incoming();
            Fixtures.folderBundle(in, "b1", "run-1", 50, 1);
            Fixtures.marker(in, "b1");
            h.service.drain();
        }
        // a new process (ledger re-read from disk) sees the same run again, then a changed one
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            Fixtures.folderBundle(in, "b1", "run-1", 50, 1);
            Fixtures.marker(in, "b1");
            assertEquals(new DrainSummary(0, 1, 0), h.service.drain());
            Fixtures.folderBundle(in, "b1", "run-1", 60, 1);
            Fixtures.marker(in, "b1");
            assertEquals(new DrainSummary(1, 1, 0), h.service.drain());
            assertTrue(Files.exists(h.layout.reports().resolve("run-1.v2.json")));
            assertEquals(2, count(h.layout.reports(), ".json"));
            assertEquals(3, count(h.layout.done(), ""));
        }
    }

    @Test
    void badBundleGoesToFailedWithItsReasonAndDrainExitsWithFour() throws IOException {
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            Path in = h.layout.incoming();
            Path b = Fixtures.folderBundle(in, "b1", "run-1", 50, 1);
            Files.writeString(b.resolve("est.csv"), "t,x,y,yaw\n0,0,0,0\n0.1,zero,0,0\n");
            Fixtures.marker(in, "b1");
            DrainSummary s = h.service.drain();
            assertEquals(new DrainSummary(0, 0, 1), s);
            assertEquals(4, s.exitCode());
            JsonNode err = JSON.readTree(h.layout.failed().resolve("b1.error.json").toFile());
            assertEquals("score", err.get("stage").asText());
            assertEquals("not_a_number", err.get("kind").asText());
            assertTrue(err.get("message").asText().startsWith("est.csv:3:"), err.toString());
            assertTrue(err.hasNonNull("time"));
            assertTrue(Files.isDirectory(h.layout.failed().resolve("b1")));
        }
    }

    @Test
    void bundlesWithoutMarkerAndHiddenOrTemporaryFilesAreLeftAlone() throws IOException {
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            Path in = h.layout.incoming();
            Fixtures.folderBundle(in, "waiting", "run-1", 50, 1);
            Fixtures.folderBundle(in, ".hidden", "run-2", 50, 2);
            Fixtures.marker(in, ".hidden");
            Fixtures.write(in.resolve("upload.zip.part"), "x");
            Fixtures.write(in.resolve("upload.zip.part.done"), "");
            assertEquals(new DrainSummary(0, 0, 0), h.service.drain());
            assertEquals(5, count(in, ""));
        }
    }

    @Test
    void withQuietCompletionABundleUnchangedForTheQuietTimeIsTakenWithoutMarker() throws IOException {
        DirectoryOptions quiet = new DirectoryOptions(1, 1, Completion.MARKER_OR_QUIET, Duration.ofSeconds(30),
                Duration.ofMillis(50));
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer(), quiet, BundleLimits.DEFAULTS)) {
            Path in = h.layout.incoming();
            Path old = Fixtures.folderBundle(in, "old", "run-old", 50, 1);
            FileTime past = FileTime.fromMillis(System.currentTimeMillis() - 60_000);
            try (Stream<Path> s = Files.walk(old)) {
                for (Path p : (Iterable<Path>) s::iterator) {
                    Files.setLastModifiedTime(p, past);
                }
            }
            Fixtures.folderBundle(in, "fresh", "run-fresh", 50, 2);
            assertEquals(new DrainSummary(1, 0, 0), h.service.drain());
            assertTrue(Files.exists(h.layout.reports().resolve("run-old.json")));
            assertTrue(Files.isDirectory(in.resolve("fresh")));
        }
    }

    @Test
    void aSlotLeftInProcessingByADeadProcessIsResumedOnStart() throws IOException {
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            // what a SIGKILL between the claim and the marker move leaves: slot with payload, marker still in incoming
            Path slot = h.layout.processing().resolve("b1");
            Fixtures.folderBundle(slot, "b1", "run-1", 50, 1);
            Fixtures.write(slot.resolve(".lock"), "");
            Fixtures.marker(h.layout.incoming(), "b1");
            assertEquals(new DrainSummary(1, 0, 0), h.service.drain());
            assertTrue(Files.exists(h.layout.reports().resolve("run-1.json")));
            assertEquals(0, count(h.layout.incoming(), ""));
            assertEquals(0, count(h.layout.processing(), ""));
            assertTrue(Files.exists(h.layout.done().resolve("b1").resolve("b1.done")));
        }
    }

    @Test
    void metricsCountRunsByOutcome() throws IOException {
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            Path in = h.layout.incoming();
            Fixtures.pair(in, "a", 50, 1);
            Fixtures.marker(in, "a");
            Fixtures.write(in.resolve("b.gt.csv"), "t,x,y,yaw\n0,0,0,0\n1,1,1,1\n");
            Fixtures.marker(in, "b"); // estimate missing
            h.service.drain();
            assertEquals(1, h.metrics.runs(org.trajeval.pipeline.Outcome.REPORTED));
            assertEquals(1, h.metrics.runs(org.trajeval.pipeline.Outcome.FAILED));
            assertEquals(0, h.metrics.inProcessing().get());
            assertFalse(Files.exists(h.layout.reports().resolve("b.json")));
        }
    }
}
