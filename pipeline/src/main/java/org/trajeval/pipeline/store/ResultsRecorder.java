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
import org.trajeval.pipeline.ReportStore;
import org.trajeval.pipeline.ledger.LedgerEntry;
import org.trajeval.store.Labels;
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
 * <p>A store that is down delays recording but loses nothing: the failure is logged once, the
 * lag gauge counts the reports not yet recorded, and a background task replays the backlog from
 * the ledger every {@code store.retry_interval_s} until the store answers. At start-up the same
 * replay catches reports committed while no recorder ran (a crash between report and store, an
 * older version, a store added later).
 */
public final class ResultsRecorder implements ReportStore.CommitListener, AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(ResultsRecorder.class);
    private static final int BATCH = 500;

    private final StoreLocation location;
    private final ReportStore reports;
    private final AtomicLong lag;
    private final Clock clock;
    private final ScheduledExecutorService replayer;
    private ResultsStore store;
    private boolean down;
    private boolean backlog = true;

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
    public void committed(String runId, int version, Path reportFile) {
        lag.incrementAndGet();
        synchronized (this) {
            if (backlog) {
                return; // the replay will take it, in ledger order
            }
            try {
                record(List.of(read(reportFile)));
                lag.decrementAndGet();
            } catch (StoreException | IOException e) {
                wentDown(e);
            }
        }
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
