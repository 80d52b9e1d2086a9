package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BiConsumer;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.RunScorer;
import org.trajeval.pipeline.StandInScorer;
import org.trajeval.pipeline.bundle.BundleLimits;

/** A run's report is filed (written, fsync'd, its ledger line appended) beside the scoring of the next run. */
class FilingBesideScoringTest {
    @TempDir
    Path root;

    @Test
    void oneWorkerScoresTheNextBundleWhileThePreviousReportIsBeingFiled() throws IOException {
        CountDownLatch bothScored = new CountDownLatch(2);
        AtomicInteger writes = new AtomicInteger();
        AtomicBoolean secondScoredDuringFirstWrite = new AtomicBoolean();
        RunScorer scorer = job -> {
            EvaluationReport r = new StandInScorer().score(job);
            bothScored.countDown();
            return r;
        };
        // the first report's writing waits (at most 10 s) for the other run to be scored: with the one
        // worker filing its own reports that run could only be scored after this write returned
        BiConsumer<Path, String> writer = (file, text) -> {
            if (writes.getAndIncrement() == 0) {
                try {
                    secondScoredDuringFirstWrite.set(bothScored.await(10, TimeUnit.SECONDS));
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
            ReportJson.writeAtomically(file, text);
        };
        DirectoryOptions oneWorker = new DirectoryOptions(1, 1, Completion.MARKER, Duration.ofSeconds(60),
                Duration.ofMillis(50));
        try (ServiceHarness h = new ServiceHarness(root, scorer, oneWorker, BundleLimits.DEFAULTS, writer)) {
            Fixtures.pair(h.layout.incoming(), "run-1", 50, 1);
            Fixtures.marker(h.layout.incoming(), "run-1");
            Fixtures.pair(h.layout.incoming(), "run-2", 50, 2);
            Fixtures.marker(h.layout.incoming(), "run-2");
            assertEquals(new DrainSummary(2, 0, 0), h.service.drain());
            assertTrue(secondScoredDuringFirstWrite.get(), "the second run was scored while the first report was written");
            assertTrue(Files.isRegularFile(h.layout.reports().resolve("run-1.json")));
            assertTrue(Files.isRegularFile(h.layout.reports().resolve("run-2.json")));
            int versions = h.ledger.locked(v -> v.latestVersion("run-1") + v.latestVersion("run-2"));
            assertEquals(2, versions);
        }
    }
}
