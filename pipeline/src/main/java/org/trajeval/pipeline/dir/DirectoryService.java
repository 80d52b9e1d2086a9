package org.trajeval.pipeline.dir;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.DirectoryStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Duration;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.Semaphore;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.trajeval.core.InputText;
import org.trajeval.core.report.ReportJson;
import org.trajeval.pipeline.EnvironmentException;
import org.trajeval.pipeline.Outcome;
import org.trajeval.pipeline.RunFailure;
import org.trajeval.pipeline.RunJob;
import org.trajeval.pipeline.RunProcessor;
import org.trajeval.pipeline.RunResult;
import org.trajeval.pipeline.Stage;
import org.trajeval.pipeline.StageException;
import org.trajeval.pipeline.bundle.BundleOpener;
import org.trajeval.pipeline.metrics.PipelineMetrics;

/**
 * The directory mode: watches {@code incoming/}, claims each complete bundle by an atomic move
 * into {@code processing/}, scores it on a bounded worker pool, writes {@code reports/RUN_ID.json}
 * and moves the bundle to {@code done/}, or to {@code failed/} with {@code NAME.error.json}.
 *
 * <p>A bundle is scored on one of {@code workers} threads and filed (its report and ledger line
 * fsync'd, then the move) on one of as many committing threads, so a worker does not wait for the
 * disk before it scores the next claimed bundle.
 *
 * <p>Backpressure: at most {@code workers + queueCapacity} bundles are claimed at once; the
 * scanner reads incoming/ as a lazy directory stream and waits for a free permit, so a backlog of
 * any size stays on disk. Start-up resumes slots left in processing/ by a process that died.
 * {@link #stop()} (e.g. on SIGTERM) stops claiming and lets in-flight runs finish.
 *
 * <p>When the service's own environment fails (a full disk, a read-only reports/ or failed/: an
 * {@link EnvironmentException}), the bundle is not the input's fault: it stays in processing/
 * (lock released, so it is resumed), one line names the OS error, and claiming stops. A drain
 * then ends with the work left counted as unfinished (exit code 7); a running service pauses
 * ({@link #MIN_BACKOFF} doubling up to {@link #MAX_BACKOFF}) and retries the slots kept.
 */
public final class DirectoryService {
    private static final Logger LOG = LoggerFactory.getLogger(DirectoryService.class);
    private static final ObjectMapper JSON = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private final DirectoryLayout layout;
    private final DirectoryOptions options;
    private final RunProcessor processor;
    private final BundleOpener opener;
    private final PipelineMetrics metrics;
    private final Clock clock;
    private final IncomingScanner scanner;
    private final Semaphore permits;
    private final ClaimNames claimNames = new ClaimNames();
    private final int maxPermits;
    private final AtomicLong reported = new AtomicLong();
    private final AtomicLong duplicates = new AtomicLong();
    private final AtomicLong failed = new AtomicLong();
    private final AtomicInteger claimedThisPass = new AtomicInteger();
    private volatile boolean stopping;
    private volatile boolean running;
    private final Object wake = new Object();
    private final AtomicLong kept = new AtomicLong();
    private volatile EnvironmentException environmentFailure;
    private Duration backoff = MIN_BACKOFF;
    private ExecutorService committers;

    /** First pause after an environment failure in a running service. */
    static final Duration MIN_BACKOFF = Duration.ofSeconds(1);
    /** Longest pause between retries after environment failures. */
    static final Duration MAX_BACKOFF = Duration.ofSeconds(60);

    /**
     * @param layout the service's folders (created if missing)
     * @param options workers, queue, completion policy
     * @param processor scores and files runs
     * @param opener opens bundles with the size limits
     * @param metrics where to count
     * @param clock clock for quiet time and error files
     */
    public DirectoryService(DirectoryLayout layout, DirectoryOptions options, RunProcessor processor,
            BundleOpener opener, PipelineMetrics metrics, Clock clock) {
        this.layout = layout.create();
        this.options = options;
        this.processor = processor;
        this.opener = opener;
        this.metrics = metrics;
        this.clock = clock;
        this.scanner = new IncomingScanner(layout.incoming(), options.completion(), options.quietTime(), clock);
        this.maxPermits = options.workers() + options.queueCapacity();
        this.permits = new Semaphore(maxPermits);
    }

    /**
     * Processes every complete bundle present (and those that complete meanwhile), then returns.
     *
     * @return what was done
     */
    public DrainSummary drain() {
        return run(true);
    }

    /** Runs until {@link #stop()}; in-flight runs finish before it returns. */
    public DrainSummary runUntilStopped() {
        return run(false);
    }

    /** Asks the service to stop claiming; {@link #runUntilStopped()} returns once in-flight runs finished. */
    public void stop() {
        stopping = true;
        synchronized (wake) {
            wake.notifyAll();
        }
    }

    /** @return true while the service runs (for /health) */
    public boolean isRunning() {
        return running && !stopping;
    }

    private DrainSummary run(boolean drain) {
        running = true;
        ExecutorService workers = Executors.newFixedThreadPool(options.workers(), r -> {
            Thread t = new Thread(r, "trajeval-worker");
            t.setDaemon(false);
            return t;
        });
        // a run's filing (report and ledger fsyncs, the move to done/) waits on the disk: on threads of
        // its own, so that a worker scores the next claimed bundle meanwhile (as eval --batch's report writer)
        committers = Executors.newFixedThreadPool(options.workers(), r -> {
            Thread t = new Thread(r, "trajeval-commit");
            t.setDaemon(false);
            return t;
        });
        StaleTempFiles.clean(layout.reports(), clock);
        StaleTempFiles.clean(layout.failed(), clock);
        try {
            resumeLeftovers(workers);
            while (!stopping) {
                if (environmentFailure != null) {
                    if (drain) {
                        awaitIdle();
                        break;
                    }
                    pauseAfterEnvironmentFailure();
                    resumeLeftovers(workers);
                    continue;
                }
                claimedThisPass.set(0);
                scanPass(workers);
                if (drain) {
                    awaitIdle();
                    if (claimedThisPass.get() == 0) {
                        break;
                    }
                } else if (claimedThisPass.get() == 0) {
                    synchronized (wake) {
                        if (!stopping) {
                            wake.wait(options.scanInterval().toMillis());
                        }
                    }
                }
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            // the workers hand their runs to the committers: those stop once the workers have
            awaitTermination(workers);
            awaitTermination(committers);
            running = false;
        }
        long unfinished = environmentFailure == null && kept.get() == 0 ? 0 : kept.get() + countKeys();
        return new DrainSummary(reported.get(), duplicates.get(), failed.get(), unfinished);
    }

    private static void awaitTermination(ExecutorService pool) {
        pool.shutdown();
        try {
            while (!pool.awaitTermination(1, TimeUnit.SECONDS)) {
                LOG.info("waiting for in-flight runs to finish");
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Waits {@link #backoff} (doubling it up to {@link #MAX_BACKOFF}), then lets the scan retry. */
    private void pauseAfterEnvironmentFailure() throws InterruptedException {
        LOG.warn("pausing {} s after: {}", backoff.toSeconds(), environmentFailure.getMessage());
        synchronized (wake) {
            if (!stopping) {
                wake.wait(backoff.toMillis());
            }
        }
        backoff = backoff.multipliedBy(2).compareTo(MAX_BACKOFF) > 0 ? MAX_BACKOFF : backoff.multipliedBy(2);
        environmentFailure = null;
        kept.set(0);
    }

    /**
     * Keeps a bundle the environment kept us from finishing: in processing/, lock released so the
     * slot can be resumed, one line with the OS reason (no stack trace), claiming stopped.
     */
    private void keep(Slot slot, EnvironmentException e) {
        kept.incrementAndGet();
        environmentFailure = e;
        LOG.warn("bundle={} stays in processing/ to be retried (not the input's fault): {}",
                InputText.escape(slot.unit().slotName()), e.getMessage());
        slot.close();
    }

    private void awaitIdle() throws InterruptedException {
        permits.acquire(maxPermits);
        permits.release(maxPermits);
    }

    private void resumeLeftovers(ExecutorService workers) throws InterruptedException {
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(layout.processing())) {
            for (Path p : ds) {
                if (stopping) {
                    return;
                }
                permits.acquire();
                Slot slot;
                try {
                    slot = Slot.resume(layout.incoming(), p);
                } catch (IOException e) {
                    LOG.warn("could not resume {}: {}", p, e.toString());
                    slot = null;
                }
                if (slot == null) {
                    permits.release();
                    continue;
                }
                LOG.info("resuming bundle={}", slot.dir().getFileName());
                submit(workers, slot);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("could not list " + layout.processing() + ": " + e.getMessage(), e);
        }
    }

    private void scanPass(ExecutorService workers) throws InterruptedException {
        long waiting = countKeys();
        metrics.queueDepth().set(waiting);
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(layout.incoming())) {
            for (Path p : ds) {
                if (stopping || environmentFailure != null) {
                    return;
                }
                String name = p.getFileName().toString();
                if (!scanner.maybeKey(name)) {
                    continue;
                }
                BundleUnit unit = scanner.completeUnit(name);
                if (unit == null) {
                    continue;
                }
                while (!permits.tryAcquire(200, TimeUnit.MILLISECONDS)) {
                    if (stopping) {
                        return;
                    }
                }
                if (environmentFailure != null) {
                    permits.release(); // failed while we waited: claim nothing more
                    return;
                }
                Slot slot;
                try {
                    slot = Slot.claim(layout.incoming(), layout.processing(), unit, claimNames);
                } catch (IOException e) {
                    environmentFailure = new EnvironmentException("claim into", layout.processing().resolve(
                            unit.slotName()), e);
                    LOG.warn("could not claim bundle={}: {}", InputText.escape(name), environmentFailure.getMessage());
                    slot = null;
                }
                if (slot == null) {
                    permits.release();
                    continue;
                }
                claimedThisPass.incrementAndGet();
                metrics.queueDepth().updateAndGet(v -> Math.max(0, v - 1));
                submit(workers, slot);
            }
        } catch (IOException e) {
            throw new UncheckedIOException("could not list " + layout.incoming() + ": " + e.getMessage(), e);
        }
    }

    private long countKeys() {
        long n = 0;
        try (DirectoryStream<Path> ds = Files.newDirectoryStream(layout.incoming())) {
            for (Path p : ds) {
                String name = p.getFileName().toString();
                if (name.endsWith(".done") && !IncomingScanner.ignored(name)) {
                    n++;
                }
            }
        } catch (IOException e) {
            LOG.warn("could not count {}: {}", layout.incoming(), e.toString());
        }
        return n;
    }

    private void submit(ExecutorService workers, Slot slot) {
        metrics.inProcessing().incrementAndGet();
        workers.execute(() -> {
            boolean handedOn = false;
            try {
                long start = System.nanoTime();
                Scoring scoring = score(slot);
                Runnable filing = () -> {
                    try {
                        file(slot, scoring, start);
                    } finally {
                        metrics.inProcessing().decrementAndGet();
                        permits.release();
                    }
                };
                handedOn = true;
                try {
                    committers.execute(filing);
                } catch (RejectedExecutionException e) {
                    filing.run(); // shut down early (an interrupted stop): filed here, as before the hand-off
                }
            } finally {
                if (!handedOn) {
                    metrics.inProcessing().decrementAndGet();
                    permits.release();
                }
            }
        });
    }

    /**
     * What a worker made of a bundle: the scored run to file, or the failed run's result, or
     * {@code kept}: the environment failed and the bundle stays in processing/.
     */
    private record Scoring(RunProcessor.Scored scored, RunResult failed, Path scratch, boolean kept) {
    }

    /** The worker's half of one bundle: open and score it (nothing durable is written). */
    private Scoring score(Slot slot) {
        BundleUnit unit = slot.unit();
        Path scratch = slot.dir().resolve(".unpacked");
        try {
            Slot.deleteTree(scratch);
            Path payload = switch (unit.kind()) {
                case FOLDER -> slot.dir().resolve(unit.name());
                case ZIP -> slot.dir().resolve(unit.name() + ".zip");
                case PAIR -> slot.dir();
                case BAG -> slot.dir().resolve(unit.name());
            };
            RunJob job = opener.open(unit.kind(), payload, unit.name(), scratch);
            return new Scoring(processor.score(job), null, scratch, false);
        } catch (StageException e) {
            return new Scoring(null, RunResult.failed(null, e.failure()), scratch, false);
        } catch (EnvironmentException e) {
            deleteScratch(scratch);
            keep(slot, e);
            return new Scoring(null, null, scratch, true);
        } catch (IOException e) {
            deleteScratch(scratch);
            keep(slot, new EnvironmentException("clear", scratch, e));
            return new Scoring(null, null, scratch, true);
        } catch (RuntimeException e) {
            LOG.error("internal error on bundle={}", unit.slotName(), e);
            return new Scoring(null, RunResult.failed(null, RunFailure.of(Stage.SCORE, e)), scratch, false);
        }
    }

    /**
     * The committer's half of one bundle: files the report (durable report, then durable ledger
     * line), then moves the bundle to done/ or failed/; whatever happens, the bundle ends there or
     * stays in processing/ for a retry.
     */
    private void file(Slot slot, Scoring scoring, long start) {
        if (scoring.kept()) {
            return;
        }
        RunResult result = scoring.failed();
        if (result == null) {
            try {
                result = processor.file(scoring.scored());
            } catch (StageException e) {
                result = RunResult.failed(null, e.failure());
            } catch (EnvironmentException e) {
                deleteScratch(scoring.scratch());
                keep(slot, e);
                return;
            } catch (RuntimeException e) {
                LOG.error("internal error on bundle={}", slot.unit().slotName(), e);
                result = RunResult.failed(null, RunFailure.of(Stage.SCORE, e));
            }
        }
        deleteScratch(scoring.scratch());
        Duration took = Duration.ofNanos(System.nanoTime() - start);
        try {
            finish(slot, result);
        } catch (EnvironmentException e) {
            keep(slot, e);
            return;
        } catch (UncheckedIOException e) {
            keep(slot, EnvironmentException.of(e));
            return;
        }
        metrics.recordRun(result.outcome(), took);
        switch (result.outcome()) {
            case REPORTED -> reported.incrementAndGet();
            case DUPLICATE -> duplicates.incrementAndGet();
            case FAILED -> failed.incrementAndGet();
        }
    }

    private static void deleteScratch(Path scratch) {
        try {
            Slot.deleteTree(scratch);
        } catch (IOException e) {
            LOG.warn("could not delete {}: {}", InputText.escape(scratch.toString()), e.toString());
        }
    }

    private void finish(Slot slot, RunResult result) {
        if (result.outcome() == Outcome.FAILED) {
            Path dest = slot.destination(layout.failed());
            RunFailure f = result.failure();
            // the message names files where they were read, in processing/SLOT: name where they are now
            String message = f.message().replace(slot.dir().toString(), dest.toString());
            ObjectNode err = JSON.createObjectNode();
            err.put("bundle", slot.unit().slotName());
            err.put("stage", f.stage().name().toLowerCase(java.util.Locale.ROOT));
            err.put("kind", f.kind());
            err.put("message", message);
            err.put("bad_input", f.badInput());
            err.put("time", clock.instant().toString());
            try {
                ReportJson.writeAtomically(layout.failed().resolve(dest.getFileName() + ".error.json"),
                        JSON.writeValueAsString(err) + "\n");
            } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
                throw new IllegalStateException(e);
            }
            slot.moveTo(dest);
            LOG.warn("failed bundle={} stage={} kind={} message=\"{}\"", InputText.escape(slot.unit().slotName()),
                    err.get("stage").asText(), f.kind(), InputText.escape(message));
        } else {
            slot.moveTo(slot.destination(layout.done()));
            LOG.info("{} run_id={} version={} bundle={} report={}", result.outcome().label(), result.runId(),
                    result.version(), InputText.escape(slot.unit().slotName()), result.report());
        }
    }
}
