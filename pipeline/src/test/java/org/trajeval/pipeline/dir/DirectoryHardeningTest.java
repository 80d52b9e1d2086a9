package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ch.qos.logback.classic.Level;
import ch.qos.logback.classic.Logger;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.classic.spi.LoggingEvent;
import ch.qos.logback.core.read.ListAppender;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.FileTime;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.slf4j.LoggerFactory;
import org.trajeval.pipeline.EscapedMessageConverter;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.LogSetup;
import org.trajeval.pipeline.ReportStore;
import org.trajeval.pipeline.RunProcessor;
import org.trajeval.pipeline.StandInScorer;
import org.trajeval.pipeline.bundle.BundleLimits;
import org.trajeval.pipeline.bundle.BundleOpener;
import org.trajeval.pipeline.ledger.Ledger;
import org.trajeval.pipeline.metrics.PipelineMetrics;

/** Issue 11's directory-mode cases: error files, stale temporary files, claim races, log forging. */
class DirectoryHardeningTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path root;

    private static List<String> names(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void theErrorFileNamesWhereTheBundleIsNowNotProcessing() throws IOException {
        try (ServiceHarness h = new ServiceHarness(root, new org.trajeval.pipeline.CoreRunScorer(1 << 20))) {
            Path in = h.layout.incoming();
            Fixtures.pair(in, "r1", 40, 1);
            Fixtures.write(in.resolve("r1.est.csv"), "t,x,y,yaw\n0,0,0,0\n1,abc,0,0\n");
            Fixtures.marker(in, "r1");
            assertEquals(new DrainSummary(0, 0, 1), h.service.drain());
            JsonNode err = JSON.readTree(h.layout.failed().resolve("r1.pair.error.json").toFile());
            String message = err.get("message").asText();
            assertTrue(message.contains("r1.est.csv:3:"), message);
            assertFalse(message.contains("processing"), message);
            assertTrue(Files.exists(h.layout.failed().resolve("r1.pair").resolve("r1.est.csv")), "the file named exists");
            assertEquals(List.of("r1.pair", "r1.pair.error.json"), names(h.layout.failed()));
        }
    }

    @Test
    void duplicateKeysInRunYamlOrABinaryRunYamlPutTheBundleInFailedWithTheKey() throws IOException {
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            Path in = h.layout.incoming();
            Path dup = Fixtures.folderBundle(in, "dup", "run-1", 20, 1);
            Fixtures.write(dup.resolve("run.yaml"), Fixtures.manifest("run-1", "bot", "gt.csv", "est.csv")
                    + "metrics: {alignment: se2}\nmetrics: {alignment: none}\n");
            Fixtures.marker(in, "dup");
            Path dupId = Fixtures.folderBundle(in, "dupid", "run-2", 20, 2);
            Fixtures.write(dupId.resolve("run.yaml"), Fixtures.manifest("run-2", "bot", "gt.csv", "est.csv")
                    + "run_id: other\n");
            Fixtures.marker(in, "dupid");
            Path bin = Fixtures.folderBundle(in, "bin", "run-3", 20, 3);
            Files.write(bin.resolve("run.yaml"), new byte[] {'r', 'u', 'n', '_', 'i', 'd', ':', ' ', (byte) 0xff, 0, 1});
            Fixtures.marker(in, "bin");
            assertEquals(new DrainSummary(0, 0, 3), h.service.drain());
            assertEquals(List.of(), names(h.layout.reports()));
            assertEquals(0, Files.size(h.layout.ledger()));
            JsonNode e1 = JSON.readTree(h.layout.failed().resolve("dup.error.json").toFile());
            assertEquals("invalid_configuration", e1.get("kind").asText());
            assertTrue(e1.get("message").asText().endsWith("Duplicate field 'metrics'"), e1.toString());
            JsonNode e2 = JSON.readTree(h.layout.failed().resolve("dupid.error.json").toFile());
            assertTrue(e2.get("message").asText().endsWith("Duplicate field 'run_id'"), e2.toString());
            JsonNode e3 = JSON.readTree(h.layout.failed().resolve("bin.error.json").toFile());
            assertEquals("not_utf8", e3.get("kind").asText(), e3.toString());
            assertTrue(e3.get("message").asText().contains("run.yaml must be UTF-8 text, byte 8 (0xFF)"), e3.toString());
        }
    }

    @Test
    void aConfigurationFileWithADuplicateKeyIsRefused() throws IOException {
        Path config = root.resolve("c.yaml");
        Fixtures.write(config, "workers: 2\nworkers: 8\n");
        org.trajeval.core.InputException e = org.junit.jupiter.api.Assertions.assertThrows(
                org.trajeval.core.InputException.class,
                () -> org.trajeval.pipeline.ConfigLoader.load(config, java.util.Map.of(), java.util.Map.of()));
        assertEquals(2, e.line());
        assertTrue(e.getMessage().endsWith("Duplicate field 'workers'"), e.getMessage());
    }

    @Test
    void staleTemporaryReportFilesAreRemovedAtStartOnlyOursAndOnlyOld() throws IOException {
        DirectoryLayout layout = new DirectoryLayout(root).create();
        Path old = Files.writeString(layout.reports().resolve(".r1.json.8071340751977.tmp"), "{\"half");
        Path fresh = Files.writeString(layout.reports().resolve(".r2.json.1234.tmp"), "{\"being written");
        Path notOurs = Files.writeString(layout.reports().resolve("notes.tmp"), "kept");
        Path oldError = Files.writeString(layout.failed().resolve(".b.error.json.99.tmp"), "{");
        FileTime hourAgo = FileTime.from(Instant.now().minus(Duration.ofHours(1)));
        for (Path p : List.of(old, notOurs, oldError)) {
            Files.setLastModifiedTime(p, hourAgo);
        }
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            assertEquals(new DrainSummary(0, 0, 0), h.service.drain());
        }
        assertFalse(Files.exists(old));
        assertFalse(Files.exists(oldError));
        assertTrue(Files.exists(fresh), "younger than 10 min: maybe another instance is writing it");
        assertTrue(Files.exists(notOurs), "not our pattern");
    }

    @Test
    void twoInstancesRacingForClaimsLeaveNoClaimFoldersAndNoWarnings() throws Exception {
        DirectoryLayout layout = new DirectoryLayout(root).create();
        int bundles = 60;
        for (int i = 0; i < bundles; i++) {
            Fixtures.pair(layout.incoming(), "run-" + i, 20, i);
            Fixtures.marker(layout.incoming(), "run-" + i);
        }
        ListAppender<ILoggingEvent> log = new ListAppender<>();
        log.start();
        Logger logger = (Logger) LoggerFactory.getLogger(DirectoryService.class);
        logger.addAppender(log);
        ExecutorService two = Executors.newFixedThreadPool(2);
        try (Ledger ledger = Ledger.open(layout.ledger())) {
            RunProcessor processor = new RunProcessor(new StandInScorer(),
                    new ReportStore(layout.reports(), ledger, Clock.systemUTC()));
            DirectoryOptions o = new DirectoryOptions(2, 2, Completion.MARKER, Duration.ofSeconds(60),
                    Duration.ofMillis(10));
            List<Future<DrainSummary>> runs = List.of(0, 1).stream().map(i -> two.submit(() -> new DirectoryService(
                    layout, o, processor, new BundleOpener(BundleLimits.DEFAULTS), PipelineMetrics.inMemory(),
                    Clock.systemUTC()).drain())).toList();
            long reported = 0;
            for (Future<DrainSummary> f : runs) {
                DrainSummary s = f.get();
                assertEquals(0, s.failed() + s.duplicates() + s.unfinished(), s.toString());
                reported += s.reported();
            }
            assertEquals(bundles, reported, "every run reported once, by one of the two");
        } finally {
            two.shutdownNow();
            logger.detachAppender(log);
        }
        assertEquals(List.of(), names(layout.processing()), "no .claim-* folder left");
        assertEquals(bundles, names(layout.reports()).size());
        assertEquals(List.of(), log.list.stream().filter(e -> e.getLevel().isGreaterOrEqual(Level.WARN))
                .map(ILoggingEvent::getFormattedMessage).toList(), "losing a claim race is normal");
    }

    @Test
    void textLogsEscapeANewlineOrTerminalEscapeInANameSoNoLineCanBeForged() throws IOException {
        LoggingEvent e = new LoggingEvent();
        e.setLevel(Level.WARN);
        e.setMessage("failed bundle={} stage={}");
        e.setArgumentArray(new Object[] {"evil\n2026-11-23T00:00:00Z INFO forged \u001b]0;PWNED\u0007", "unpack"});
        String line = new EscapedMessageConverter().convert(e);
        assertEquals("failed bundle=evil\\n2026-11-23T00:00:00Z INFO forged \\e]0;PWNED\\a stage=unpack", line);
        assertTrue(LogSetup.TEXT_PATTERN.contains("%emsg%n") && !LogSetup.TEXT_PATTERN.contains("%msg"),
                "the text pattern uses %emsg");
    }
}
