package org.trajeval.pipeline.dir;

import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.util.function.BiConsumer;
import org.trajeval.core.report.ReportJson;
import org.trajeval.pipeline.ReportStore;
import org.trajeval.pipeline.RunProcessor;
import org.trajeval.pipeline.RunScorer;
import org.trajeval.pipeline.bundle.BundleLimits;
import org.trajeval.pipeline.bundle.BundleOpener;
import org.trajeval.pipeline.ledger.Ledger;
import org.trajeval.pipeline.metrics.PipelineMetrics;

/** A directory service on a folder, for tests; close() closes its ledger. */
final class ServiceHarness implements AutoCloseable {
    final DirectoryLayout layout;
    final Ledger ledger;
    final PipelineMetrics metrics = PipelineMetrics.inMemory();
    final DirectoryService service;

    ServiceHarness(Path root, RunScorer scorer, DirectoryOptions options, BundleLimits limits) {
        this(root, scorer, options, limits, ReportJson::writeAtomically);
    }

    /** With the function that writes report files (tests inject storage faults there). */
    ServiceHarness(Path root, RunScorer scorer, DirectoryOptions options, BundleLimits limits,
            BiConsumer<Path, String> reportWriter) {
        layout = new DirectoryLayout(root).create();
        ledger = Ledger.open(layout.ledger());
        service = new DirectoryService(layout, options, new RunProcessor(scorer,
                new ReportStore(layout.reports(), ledger, Clock.systemUTC(), reportWriter)), new BundleOpener(limits),
                metrics, Clock.systemUTC());
    }

    ServiceHarness(Path root, RunScorer scorer) {
        this(root, scorer, new DirectoryOptions(2, 2, Completion.MARKER, Duration.ofSeconds(60), Duration.ofMillis(50)),
                BundleLimits.DEFAULTS);
    }

    @Override
    public void close() {
        ledger.close();
    }
}
