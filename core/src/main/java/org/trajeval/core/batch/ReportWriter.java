package org.trajeval.core.batch;

import java.nio.file.Path;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;

/**
 * Writes a batch's reports on a thread of its own, so that the scoring threads do not wait for
 * the disk: each report is written atomically as before (temporary file, fsync, rename, fsync of
 * the folder: about 0.7 ms of waiting per report on the benchmark machine, 5-7 % of a 10^4-pose
 * pair's time). At most {@link #QUEUED} reports wait; when that many do, the thread that hands
 * one in writes it itself (memory stays bounded). A row is finished (handed to its callback) only
 * once its report is on disk, or with {@link BatchResult#WRITE_FAILED} when it could not be
 * written; {@link #close} returns once every report handed in is finished.
 */
final class ReportWriter implements AutoCloseable {
    /** Reports that may wait for the writing thread. */
    static final int QUEUED = 8;

    private final ThreadPoolExecutor thread;
    /** The first exception a row's callback threw on the writing thread, rethrown by {@link #close}. */
    private final AtomicReference<RuntimeException> failure = new AtomicReference<>();

    ReportWriter() {
        thread = new ThreadPoolExecutor(1, 1, 0L, TimeUnit.MILLISECONDS, new ArrayBlockingQueue<>(QUEUED), r -> {
            Thread t = new Thread(r, "trajeval-report-writer");
            t.setDaemon(true);
            return t;
        }, new ThreadPoolExecutor.CallerRunsPolicy());
    }

    /**
     * Writes {@code json} as {@code reportDir/NAME.json} (NAME: the pair's report name), then hands
     * the pair's row to {@code finished}: scored, or failed with {@link BatchResult#WRITE_FAILED}.
     */
    void write(BatchPair pair, EvaluationReport report, String json, Path reportDir, Consumer<BatchResult> finished) {
        thread.execute(() -> {
            try {
                finished.accept(writeNow(pair, report, json, reportDir));
            } catch (RuntimeException e) {
                failure.compareAndSet(null, e);
            }
        });
    }

    /** @return the row of a pair whose report is written now, on the calling thread */
    static BatchResult writeNow(BatchPair pair, EvaluationReport report, String json, Path reportDir) {
        String file = pair.reportName() + ".json";
        try {
            ReportJson.writeAtomically(reportDir.resolve(file), json);
        } catch (java.io.UncheckedIOException e) {
            return BatchResult.failed(pair, BatchResult.WRITE_FAILED, "cannot write " + reportDir.resolve(file)
                    + ": " + e.getCause().getMessage());
        } catch (RuntimeException e) { // as at a top-level handler: the row says which, the batch goes on
            return BatchRunner.failed(pair, e);
        }
        return BatchResult.scored(pair, report, file);
    }

    /**
     * Waits until every report handed in is written and its row finished.
     *
     * @throws RuntimeException the first exception a row's callback threw on the writing thread
     */
    @Override
    public void close() {
        thread.shutdown();
        try {
            while (!thread.awaitTermination(1, TimeUnit.MINUTES)) {
                // a slow disk: keep waiting, the rows must all be finished before the summary
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while writing the reports", e);
        }
        if (failure.get() != null) {
            throw failure.get();
        }
    }
}
