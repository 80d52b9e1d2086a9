package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ch.qos.logback.classic.Logger;
import ch.qos.logback.classic.spi.ILoggingEvent;
import ch.qos.logback.core.read.ListAppender;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.function.BiConsumer;
import java.util.stream.Stream;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.io.TempDir;
import org.slf4j.LoggerFactory;
import org.trajeval.core.report.ReportJson;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.StandInScorer;
import org.trajeval.pipeline.bundle.BundleLimits;

/**
 * Our own storage failing is never the input's fault: with a full disk or a read-only reports/, a
 * drain keeps every bundle where it can be retried (processing/ or incoming/), puts nothing in
 * failed/, writes no report and no ledger line, logs one line per kept bundle naming the OS error
 * (no stack trace), counts the work as unfinished and exits with 7. Once the fault is gone, the next
 * drain reports every run exactly once.
 */
class EnvironmentFailureTest {
    private static final int BUNDLES = 12;

    @TempDir
    Path tmp;
    private Path mounted;
    private ListAppender<ILoggingEvent> log;

    @AfterEach
    void unmount() {
        if (log != null) {
            ((Logger) LoggerFactory.getLogger(DirectoryService.class)).detachAppender(log);
        }
        if (mounted != null) {
            StorageFaults.unmount(mounted);
        }
    }

    private void captureLog() {
        log = new ListAppender<>();
        log.start();
        ((Logger) LoggerFactory.getLogger(DirectoryService.class)).addAppender(log);
    }

    private static DirectoryOptions options() {
        return new DirectoryOptions(2, 2, Completion.MARKER, Duration.ofSeconds(60), Duration.ofMillis(50));
    }

    private static void drop(Path incoming) {
        for (int i = 0; i < BUNDLES; i++) {
            Fixtures.pair(incoming, "run-" + i, 40, i);
            Fixtures.marker(incoming, "run-" + i);
        }
    }

    private static long entries(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.count();
        }
    }

    private static long bundlesLeft(DirectoryLayout layout) throws IOException {
        long markers;
        try (Stream<Path> s = Files.list(layout.incoming())) {
            markers = s.filter(p -> p.getFileName().toString().endsWith(".done")).count();
        }
        return markers + entries(layout.processing());
    }

    /** @param tryReal mount a real small file system if this machine allows it; false: inject the fault */
    @ParameterizedTest(name = "real fault if possible: {0}")
    @ValueSource(booleans = {true, false})
    void aFullDiskLeavesEveryBundleToRetryAndTheDrainExitsUnfinished(boolean tryReal) throws IOException {
        Path root = tmp.resolve("root");
        Files.createDirectories(root);
        boolean real = tryReal && StorageFaults.mountTmpfs(root, 2L << 20);
        if (real) {
            mounted = root;
        }
        System.out.println("disk full: " + (real ? "real 2 MiB tmpfs filled to the last page" : "injected ENOSPC"));
        BiConsumer<Path, String> writer = real ? ReportJson::writeAtomically
                : StorageFaults.failingWriter("No space left on device");
        captureLog();
        DirectoryLayout layout;
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer(), options(), BundleLimits.DEFAULTS, writer)) {
            layout = h.layout;
            drop(layout.incoming());
            if (real) {
                StorageFaults.fill(root);
            }
            DrainSummary s = h.service.drain();

            assertEquals(new DrainSummary(0, 0, 0, BUNDLES), s);
            assertEquals(DrainSummary.UNFINISHED_EXIT, s.exitCode());
            assertEquals(BUNDLES, bundlesLeft(layout), "every bundle is in incoming/ or processing/");
            assertEquals(0, entries(layout.failed()), "nothing is the input's fault");
            assertEquals(0, entries(layout.done()));
            assertEquals(0, entries(layout.reports()), "no report, no temporary file left");
            assertEquals(0, Files.size(layout.ledger()), "no ledger line");
            List<ILoggingEvent> kept = log.list.stream()
                    .filter(e -> e.getFormattedMessage().contains("stays in processing/")).toList();
            assertTrue(kept.size() >= 1 && kept.size() <= 4, "claiming stops: at most workers + queue (4) kept, "
                    + "one line each: " + kept.size());
            for (ILoggingEvent e : log.list) {
                assertEquals(null, e.getThrowableProxy(), "no stack trace: " + e.getFormattedMessage());
            }
            assertTrue(kept.get(0).getFormattedMessage().endsWith("No space left on device"),
                    kept.get(0).getFormattedMessage());
        }
        if (real) {
            try (Stream<Path> s = Files.list(root)) {
                for (Path p : s.filter(p -> p.getFileName().toString().startsWith("filler")).toList()) {
                    Files.delete(p);
                }
            }
        }
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            DrainSummary s = h.service.drain();
            assertEquals(new DrainSummary(BUNDLES, 0, 0, 0), s, "the retry reports every run once");
            assertEquals(0, s.exitCode());
            assertEquals(BUNDLES, entries(layout.reports()));
            assertEquals(0, entries(layout.processing()));
            assertEquals(BUNDLES, Files.readAllLines(layout.ledger()).size());
        }
    }

    @ParameterizedTest(name = "real fault if possible: {0}")
    @ValueSource(booleans = {true, false})
    void aReadOnlyReportsFolderNeverMarksGoodBundlesAsBadInput(boolean tryReal) throws IOException {
        Path root = tmp.resolve("root");
        DirectoryLayout layout = new DirectoryLayout(root).create();
        boolean real = tryReal && StorageFaults.mountTmpfs(layout.reports(), 1L << 20)
                && StorageFaults.remountReadOnly(layout.reports());
        if (tryReal && !real) {
            StorageFaults.unmount(layout.reports()); // mounted but not remounted read-only
        }
        if (real) {
            mounted = layout.reports();
        }
        System.out.println("read-only reports/: " + (real ? "real tmpfs remounted ro" : "injected EROFS"));
        BiConsumer<Path, String> writer = real ? ReportJson::writeAtomically
                : StorageFaults.failingWriter("Read-only file system");
        captureLog();
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer(), options(), BundleLimits.DEFAULTS, writer)) {
            for (int i = 0; i < 3; i++) {
                Fixtures.folderBundle(layout.incoming(), "b" + i, "run-" + i, 40, i);
                Fixtures.marker(layout.incoming(), "b" + i);
            }
            DrainSummary s = h.service.drain();
            assertEquals(new DrainSummary(0, 0, 0, 3), s);
            assertEquals(DrainSummary.UNFINISHED_EXIT, s.exitCode());
            assertEquals(0, entries(layout.failed()), "good bundles are not bad input");
            assertEquals(3, bundlesLeft(layout));
            assertTrue(log.list.stream().anyMatch(e -> e.getFormattedMessage().endsWith("Read-only file system")),
                    "the OS error is named");
        }
    }
}
