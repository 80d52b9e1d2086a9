package org.trajeval.pipeline.store;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.trajeval.pipeline.PipelineConfig;
import org.trajeval.pipeline.PipelineReport;
import org.trajeval.pipeline.ReportStore;
import org.trajeval.pipeline.ledger.LedgerEntry;
import org.trajeval.store.Labels;
import org.trajeval.store.PipelineFields;
import org.trajeval.store.ReportRecords;
import org.trajeval.store.ResultsStore;
import org.trajeval.store.RunRecord;
import org.trajeval.store.StoreException;
import org.trajeval.store.StoreLocation;

/**
 * Records every report the pipeline commits in the results store, after the report file and its
 * ledger line (the source of truth). Idempotent: rows are keyed by the report's content hash, so a
 * report recorded twice (by a replay, another instance or {@code trajeval db import}) is one row.
 *
 * <p>Recording takes the report in hand (not read back from its file) and is batched: a worker only
 * queues the report; the recorder's thread records what was queued in the last {@link #FLUSH_MS} ms
 * in one transaction (a worker that finds {@link #BATCH} queued records them itself). A report
 * whose ledger line is durable but whose row is not (a crash, a store down) is recorded by the
 * replay from the ledger below: exactly once, as rows are keyed.
 *
 * <p>A store that is down delays recording but loses nothing: the failure is logged once, the
 * lag gauge counts the reports not yet recorded, and a background task replays the backlog from
 * the ledger every {@code store.retry_interval_s} until the store answers. At start-up the same
 * replay catches reports committed while no recorder ran (a crash between report and store, an
 * older version, a store added later).
 */
public final class ResultsRecorder implements ReportStore.CommitListener, AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(ResultsRecorder.class);
    private static final int BATCH = 500;
    /** How long a committed report may wait for others to share its transaction (ms). */
    static final long FLUSH_MS = 100;

    private final StoreLocation location;
    private final ReportStore reports;
    private final AtomicLong lag;
    private final Clock clock;
    private final ScheduledExecutorService replayer;
    private ResultsStore store;
    private boolean down;
    private boolean backlog = true;
    /** Committed reports not yet recorded, guarded by itself (not by this: workers never wait for the store). */
    private final List<Pending> queued = new ArrayList<>();
    private boolean flushScheduled;

    /** A committed report waiting to be recorded. */
    private record Pending(Path file, PipelineReport report) {
    }

    private ResultsRecorder(StoreLocation location, ReportStore reports, AtomicLong lag, Clock clock,
            Duration retry) {
        this.location = location;
        this.reports = reports;
        this.lag = lag;
        this.clock = clock;
        this.replayer = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "trajeval-store-replay");
            t.setDaemon(true);
            return t;
        });
        long ms = Math.max(100, retry.toMillis());
        replayer.scheduleWithFixedDelay(this::replayIfBehind, 0, ms, TimeUnit.MILLISECONDS);
    }

    /**
     * Attaches a recorder to a report store per the configuration's {@code store.db}.
     *
     * @param c the configuration
     * @param reports the report store both modes commit through
     * @param lag the gauge of reports not yet recorded
     * @param env the environment (credentials)
     * @return the report store that also records, and the recorder (null when {@code store.db} is none)
     * @throws StoreException BAD_LOCATION on a malformed {@code store.db} or credential setting
     */
    public static Attached attach(PipelineConfig c, ReportStore reports, AtomicLong lag, Map<String, String> env) {
        String db = c.store().db().strip();
        if ("none".equals(db)) {
            return new Attached(reports, null);
        }
        StoreLocation loc = db.isEmpty() ? StoreLocation.sqlite(c.rootPath().resolve("trajeval.db"))
                : StoreLocation.parse(db, env);
        ResultsRecorder r = new ResultsRecorder(loc, reports, lag, Clock.systemUTC(),
                Duration.ofMillis(Math.round(c.store().retryIntervalS() * 1000)));
        return new Attached(reports.withListener(r), r);
    }

    /**
     * @param reports the report store to commit through
     * @param recorder the recorder to close at shutdown, or null
     */
    public record Attached(ReportStore reports, ResultsRecorder recorder) {
    }

    @Override
    public void committed(String runId, int version, Path reportFile, PipelineReport report) {
        lag.incrementAndGet();
        boolean schedule;
        boolean full;
        synchronized (queued) {
            queued.add(new Pending(reportFile, report));
            full = queued.size() >= BATCH;
            schedule = !full && !flushScheduled;
            flushScheduled |= schedule;
        }
        if (full) {
            flush(); // the store lags behind the workers: record the batch here, holding this worker back
        } else if (schedule) {
            try {
                replayer.schedule(this::flush, FLUSH_MS, TimeUnit.MILLISECONDS);
            } catch (java.util.concurrent.RejectedExecutionException closing) {
                flush();
            }
        }
    }

    /**
     * Records the queued reports in one transaction. While the store is behind (down, or not yet
     * caught up at start-up) they are left to the replay, which reads them from the ledger, where
     * their lines are durable already.
     */
    private void flush() {
        List<Pending> batch;
        synchronized (queued) {
            batch = new ArrayList<>(queued);
            queued.clear();
            flushScheduled = false;
        }
        if (batch.isEmpty()) {
            return;
        }
        synchronized (this) {
            if (backlog) {
                return; // the replay will take them, in ledger order
            }
            try {
                List<RunRecord> records = new ArrayList<>(batch.size());
                for (Pending p : batch) {
                    records.add(ReportRecords.fromPipeline(fields(p.report()), p.file().toString(), Labels.none()));
                }
                record(records);
                lag.addAndGet(-batch.size());
            } catch (RuntimeException e) {
                wentDown(e); // the replay from the ledger records them (or says why it cannot)
            }
        }
    }

    /** @return what the store keeps of a report in hand: the fields its file holds */
    static PipelineFields fields(PipelineReport r) {
        return new PipelineFields(r.runId(), r.runVersion(), r.contentSha256(), r.processedAt(), r.robotId(),
                r.site(), r.sequence(), r.method(), r.softwareVersion(), r.seed(), r.tags(), r.factors(),
                r.resources() == null ? null : r.resources().wallTimeS(),
                r.resources() == null ? null : r.resources().peakMemoryMib(), r.domain(), r.scenario(),
                r.simulator(), r.environment(), r.modality(), r.groundTruth(), r.evaluation());
    }

    /** Replays the ledger's reports the store lacks, when behind; the scheduled task. */
    private void replayIfBehind() {
        synchronized (this) {
            if (!backlog) {
                return;
            }
        }
        replay();
    }

    /**
     * Records every ledger entry the store lacks.
     *
     * @return how many were recorded, or -1 when the store is (still) down
     */
    public synchronized int replay() {
        try {
            Map<String, LedgerEntry> byKey = new HashMap<>();
            for (LedgerEntry e : reports.ledger().entries()) {
                byKey.put(ReportRecords.pipelineKey(e.contentHash(), Labels.none()), e);
            }
            Set<String> present = store().present(byKey.keySet());
            List<RunRecord> batch = new ArrayList<>();
            int recorded = 0;
            long missing = byKey.size() - present.size();
            for (Map.Entry<String, LedgerEntry> e : byKey.entrySet()) {
                if (present.contains(e.getKey())) {
                    continue;
                }
                try {
                    batch.add(read(reports.reportFile(e.getValue().runId(), e.getValue().version())));
                } catch (NoSuchFileException gone) {
                    LOG.warn("results store: report {} of the ledger is gone; not recorded", gone.getFile());
                    missing--;
                    continue;
                }
                if (batch.size() >= BATCH) {
                    recorded += record(batch);
                    batch.clear();
                }
            }
            recorded += record(batch);
            lag.set(0);
            if (down || recorded > 0) {
                LOG.info("results store {}: {} recorded from the ledger ({} missing)", location, recorded, missing);
            }
            down = false;
            backlog = false;
            return recorded;
        } catch (StoreException | IOException e) {
            wentDown(e);
            return -1;
        }
    }

    private int record(List<RunRecord> batch) {
        return batch.isEmpty() ? 0 : store().record(batch);
    }

    private RunRecord read(Path file) throws IOException {
        return ReportRecords.fromPipeline(Files.readString(file, StandardCharsets.UTF_8), file.toString(),
                Labels.none());
    }

    private ResultsStore store() {
        if (store == null) {
            store = ResultsStore.open(location, clock);
        }
        return store;
    }

    private void wentDown(Exception e) {
        if (!down) {
            LOG.warn("results store {} unavailable ({}): recording is delayed and replayed from the ledger",
                    location, e.getMessage());
        }
        down = true;
        backlog = true;
        if (store != null) {
            store.close();
            store = null;
        }
    }

    /** Stops the replays; makes one last attempt when behind (bounded by the store's own timeouts). */
    @Override
    public void close() {
        replayer.shutdownNow();
        try {
            replayer.awaitTermination(30, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        flush();
        synchronized (this) {
            if (backlog) {
                replay();
            }
            if (store != null) {
                store.close();
                store = null;
            }
        }
    }
}
