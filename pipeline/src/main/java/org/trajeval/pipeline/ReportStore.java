package org.trajeval.pipeline;

import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.util.Optional;
import java.util.function.BiConsumer;
import org.trajeval.core.Version;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;
import org.trajeval.pipeline.bundle.ContentHash;
import org.trajeval.pipeline.ledger.Ledger;
import org.trajeval.pipeline.ledger.LedgerEntry;

/**
 * Files reports: {@code reports/RUN_ID.json} for a run's first content, {@code RUN_ID.vN.json}
 * for its N-th distinct content, each written atomically (temp file, fsync, rename, 0644) and
 * then recorded in the ledger. The decision "new, changed or already reported" and the write are
 * one section under the ledger's lock, so two workers (or processes) never report a run twice.
 *
 * <p>Crash safety: a crash after the report but before the ledger line leaves a complete report;
 * the retry computes the same version and rewrites the same file with the same content.
 */
public final class ReportStore {
    private final Path reportsDir;
    private final Ledger ledger;
    private final Clock clock;
    private final BiConsumer<Path, String> writer;
    private final CommitListener listener;

    /** Told of every report this store commits, after its file and ledger line are durable. */
    public interface CommitListener {
        /**
         * @param runId the run id
         * @param version the report's version
         * @param reportFile the report file
         * @param report the report as written to that file (in hand: no need to read it back)
         */
        void committed(String runId, int version, Path reportFile, PipelineReport report);
    }

    /**
     * @param reportsDir folder of the report files
     * @param ledger the ledger shared by every worker
     * @param clock clock for {@code processed_at}
     */
    public ReportStore(Path reportsDir, Ledger ledger, Clock clock) {
        this(reportsDir, ledger, clock, ReportJson::writeAtomically);
    }

    /**
     * As above, with the function that writes a report file atomically (tests inject storage faults here:
     * it throws {@link java.io.UncheckedIOException} when the file cannot be written).
     */
    public ReportStore(Path reportsDir, Ledger ledger, Clock clock, BiConsumer<Path, String> writer) {
        this(reportsDir, ledger, clock, writer, (id, v, f, r) -> { });
    }

    private ReportStore(Path reportsDir, Ledger ledger, Clock clock, BiConsumer<Path, String> writer,
            CommitListener listener) {
        this.reportsDir = reportsDir;
        this.ledger = ledger;
        this.clock = clock;
        this.writer = writer;
        this.listener = listener;
    }

    /** @return this store, also telling {@code l} of every committed report (e.g. the results store recorder) */
    public ReportStore withListener(CommitListener l) {
        return new ReportStore(reportsDir, ledger, clock, writer, l);
    }

    /** @return the ledger */
    public Ledger ledger() {
        return ledger;
    }

    /** @return the report file of a run version */
    public Path reportFile(String runId, int version) {
        return reportsDir.resolve(version == 1 ? runId + ".json" : runId + ".v" + version + ".json");
    }

    /** @return the folder of a run version's figures ({@code RUN_ID.plots}, {@code RUN_ID.vN.plots}) */
    public Path plotsFolder(String runId, int version) {
        return reportsDir.resolve(version == 1 ? runId + ".plots" : runId + ".v" + version + ".plots");
    }

    /** @return the folder reports are filed in (drafts of figures are drawn there too) */
    public Path reportsDir() {
        return reportsDir;
    }

    /** @return the earlier report of this content, if the run was reported with it (no lock; a hint) */
    public boolean probablyReported(String runId, ContentHash hash) {
        return ledger.probablyReported(runId, hash.content());
    }

    /** @return the ledger entry of this content, if it was reported (reads the ledger under its lock) */
    public Optional<LedgerEntry> find(String runId, ContentHash hash) {
        return ledger.locked(v -> v.find(runId, hash.content()));
    }

    /**
     * Writes the report unless this content was reported before.
     *
     * @return REPORTED with the new version and file, or DUPLICATE with the earlier ones
     */
    public RunResult commit(RunJob job, ContentHash hash, EvaluationReport evaluation) {
        return commit(job, hash, evaluation, null);
    }

    /**
     * As {@link #commit(RunJob, ContentHash, EvaluationReport)}, moving the run's drawn figures
     * into place ({@link #plotsFolder}) before the report is written; when that move fails, the
     * report says so in a {@code plot_failed} warning and the run is reported all the same.
     *
     * @param plotsDraft a draft folder of figures ({@link RunPlots}), or null
     */
    public RunResult commit(RunJob job, ContentHash hash, EvaluationReport evaluation, Path plotsDraft) {
        Committed c = commitLocked(job, hash, evaluation, plotsDraft);
        RunResult r = c.result();
        if (r.outcome() == Outcome.REPORTED) {
            listener.committed(r.runId(), r.version(), r.report(), c.report());
        }
        return r;
    }

    /** A commit's result and the report it wrote (null for a duplicate). */
    private record Committed(RunResult result, PipelineReport report) {
    }

    private Committed commitLocked(RunJob job, ContentHash hash, EvaluationReport scored, Path plotsDraft) {
        RunMetadata m = job.metadata();
        return ledger.locked(view -> {
            Optional<LedgerEntry> earlier = view.find(m.runId(), hash.content());
            if (earlier.isPresent()) {
                int v = earlier.get().version();
                return new Committed(new RunResult(Outcome.DUPLICATE, m.runId(), v, reportFile(m.runId(), v), null,
                        earlier.get().source()), null);
            }
            int version = view.latestVersion(m.runId()) + 1;
            EvaluationReport evaluation = scored;
            if (plotsDraft != null) {
                try {
                    RunPlots.publish(plotsDraft, plotsFolder(m.runId(), version));
                } catch (java.io.IOException e) {
                    evaluation = scored.withWarning(RunProcessor.plotFailed(e));
                }
            }
            Instant now = clock.instant();
            PipelineReport report = new PipelineReport(PipelineReport.SCHEMA, PipelineReport.SCHEMA_VERSION,
                    Version.TOOL, m.runId(), m.robotId(), m.sequence(), m.method(), m.seed(), m.labels().site(),
                    m.labels().softwareVersion(), m.labels().tags().isEmpty() ? null : m.labels().tags(),
                    m.about().domain(), m.about().simulator(), m.about().scenario(),
                    m.about().factors().isEmpty() ? null : m.about().factors(), m.about().environment(),
                    m.about().modality(), m.about().groundTruth(), m.resources() == null ? null
                            : new PipelineReport.Resources(m.resources().wallTimeS(), m.resources().peakMemoryMib(),
                                    m.resources().cpuTimeS(), m.resources().device()), version,
                    hash.content(), hash.reference(), hash.estimate(), job.source(), now.toString(), evaluation);
            Path file = reportFile(m.runId(), version);
            writer.accept(file, ReportJson.toJson(report));
            view.append(new LedgerEntry(m.runId(), hash.content(), version, now.toEpochMilli(), job.source()));
            return new Committed(new RunResult(Outcome.REPORTED, m.runId(), version, file, null, null), report);
        });
    }
}
