package org.trajeval.pipeline;

import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
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
 * then recorded in the ledger. The decision "new, changed or already reported" and the rename are
 * one section under the ledger's lock, so two workers (or processes) never report a run twice.
 *
 * <p>Group commit ({@link GroupCommit}): a report is written and fsync'd beside its name before the
 * lock, for the version the ledger suggests (rewritten under the lock when another report took that
 * version meanwhile); the runs that wait for the lock together are then committed in one section:
 * their reports renamed into place, the folder fsync'd once, their ledger lines appended with one
 * write and one fsync. For every run the order stays: report durable, then its ledger line durable,
 * then {@link #commit} returns (and only then does the bundle move to done/).
 *
 * <p>Crash safety: a crash after the report but before the ledger line leaves a complete report;
 * the retry computes the same version and rewrites the same file with the same content.
 */
public final class ReportStore {
    private final Path reportsDir;
    private final Ledger ledger;
    private final Clock clock;
    private final ReportFiles files;
    private final CommitListener listener;
    private final GroupCommit<Pending> group;

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
        this(reportsDir, ledger, clock, ReportFiles.durable(), (id, v, f, r) -> { });
    }

    /**
     * As above, with the function that writes a report file atomically (tests inject storage faults here:
     * it throws {@link java.io.UncheckedIOException} when the file cannot be written).
     */
    public ReportStore(Path reportsDir, Ledger ledger, Clock clock, BiConsumer<Path, String> writer) {
        this(reportsDir, ledger, clock, ReportFiles.writtenBy(writer), (id, v, f, r) -> { });
    }

    private ReportStore(Path reportsDir, Ledger ledger, Clock clock, ReportFiles files, CommitListener listener) {
        this.reportsDir = reportsDir;
        this.ledger = ledger;
        this.clock = clock;
        this.files = files;
        this.listener = listener;
        this.group = new GroupCommit<>(this::commitGroup);
    }

    /** As the public constructor, with the report files' two steps given (tests observe them). */
    static ReportStore withFiles(Path reportsDir, Ledger ledger, Clock clock, ReportFiles files) {
        return new ReportStore(reportsDir, ledger, clock, files, (id, v, f, r) -> { });
    }

    /** @return this store, also telling {@code l} of every committed report (e.g. the results store recorder) */
    public ReportStore withListener(CommitListener l) {
        return new ReportStore(reportsDir, ledger, clock, files, l);
    }

    /** @return how many group commits this store made (each one ledger fsync; tests) */
    long groups() {
        return group.groups();
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
        Pending p = new Pending(job, hash, evaluation, plotsDraft, clock.instant());
        if (plotsDraft == null) {
            // written and fsync'd before the lock, for the version the ledger suggests now
            String runId = job.metadata().runId();
            if (!ledger.probablyReported(runId, hash.content())) {
                p.stage(ledger.probableLatestVersion(runId) + 1);
            }
        }
        Committed c = group.submit(p);
        RunResult r = c.result();
        if (r.outcome() == Outcome.REPORTED) {
            listener.committed(r.runId(), r.version(), r.report(), c.report());
        }
        return r;
    }

    /** A commit's result and the report it wrote (null for a duplicate). */
    private record Committed(RunResult result, PipelineReport report) {
    }

    /** One run waiting for its group commit, with its report staged for a version (or not yet). */
    private final class Pending extends GroupCommit.Request<Committed> {
        final RunJob job;
        final ContentHash hash;
        final EvaluationReport evaluation;
        final Path plotsDraft;
        final Instant now;
        PipelineReport report;
        ReportFiles.Staged staged;
        int stagedVersion;
        Pending duplicateOf;

        Pending(RunJob job, ContentHash hash, EvaluationReport evaluation, Path plotsDraft, Instant now) {
            this.job = job;
            this.hash = hash;
            this.evaluation = evaluation;
            this.plotsDraft = plotsDraft;
            this.now = now;
        }

        String runId() {
            return job.metadata().runId();
        }

        /** Writes (fsync'd, not in place) the report of {@code version}, replacing one staged before. */
        void stage(int version) {
            stage(version, evaluation);
        }

        void stage(int version, EvaluationReport scored) {
            discard();
            report = report(job, hash, version, now, scored);
            staged = files.stage(reportFile(runId(), version), ReportJson.toJson(report));
            stagedVersion = version;
        }

        void discard() {
            if (staged != null) {
                files.discard(staged);
                staged = null;
            }
        }
    }

    /**
     * Commits a group under one ledger lock: decides each run (duplicate, or its version, counting the
     * group's own earlier runs), renames the reports into place, fsyncs the folder once, appends the
     * ledger lines with one fsync. A run whose report cannot be renamed fails alone; a failed ledger
     * append fails every run of the group that was to be reported (retried later, as after a crash).
     */
    private void commitGroup(List<Pending> pendings) {
        try {
            ledger.locked(view -> {
                Map<String, Pending> reportedNow = new HashMap<>(); // run id + content -> its run in this group
                Map<String, Integer> latestNow = new HashMap<>(); // run id -> highest version in this group
                List<Pending> toReport = new ArrayList<>();
                List<Pending> duplicatesNow = new ArrayList<>(); // of a run reported earlier in this group
                List<LedgerEntry> lines = new ArrayList<>();
                for (Pending p : pendings) {
                    String runId = p.runId();
                    Optional<LedgerEntry> earlier = view.find(runId, p.hash.content());
                    if (earlier.isPresent()) {
                        p.discard();
                        int v = earlier.get().version();
                        p.complete(new Committed(new RunResult(Outcome.DUPLICATE, runId, v, reportFile(runId, v),
                                null, earlier.get().source()), null));
                        continue;
                    }
                    Pending sameGroup = reportedNow.get(runId + '\t' + p.hash.content());
                    if (sameGroup != null) {
                        p.discard();
                        p.duplicateOf = sameGroup; // completed once that report's ledger line is durable
                        duplicatesNow.add(p);
                        continue;
                    }
                    int version = Math.max(view.latestVersion(runId), latestNow.getOrDefault(runId, 0)) + 1;
                    try {
                        if (p.plotsDraft != null) {
                            EvaluationReport evaluation = p.evaluation;
                            try {
                                RunPlots.publish(p.plotsDraft, plotsFolder(runId, version));
                            } catch (java.io.IOException e) {
                                evaluation = p.evaluation.withWarning(RunProcessor.plotFailed(e));
                            }
                            p.stage(version, evaluation);
                        } else if (p.staged == null || p.stagedVersion != version) {
                            p.stage(version); // another report took the version guessed before the lock
                        }
                        files.publish(p.staged);
                    } catch (RuntimeException e) {
                        p.discard();
                        p.fail(e);
                        continue;
                    }
                    p.staged = null; // in place now
                    reportedNow.put(runId + '\t' + p.hash.content(), p);
                    latestNow.put(runId, version);
                    toReport.add(p);
                    lines.add(new LedgerEntry(runId, p.hash.content(), version, p.now.toEpochMilli(), p.job.source()));
                }
                if (!toReport.isEmpty()) {
                    files.syncFolder(reportsDir);
                    view.appendAll(lines);
                }
                for (Pending p : toReport) {
                    p.complete(new Committed(new RunResult(Outcome.REPORTED, p.runId(), p.stagedVersion,
                            reportFile(p.runId(), p.stagedVersion), null, null), p.report));
                }
                for (Pending p : duplicatesNow) {
                    int v = p.duplicateOf.stagedVersion;
                    p.complete(new Committed(new RunResult(Outcome.DUPLICATE, p.runId(), v, reportFile(p.runId(), v),
                            null, p.duplicateOf.job.source()), null));
                }
                return null;
            });
        } finally {
            for (Pending p : pendings) {
                if (!p.isDone()) {
                    p.discard();
                }
            }
        }
    }

    /** @return the report of a run version as filed, {@code processed_at} = {@code now} */
    private static PipelineReport report(RunJob job, ContentHash hash, int version, Instant now,
            EvaluationReport evaluation) {
        RunMetadata m = job.metadata();
        return new PipelineReport(PipelineReport.SCHEMA, PipelineReport.SCHEMA_VERSION,
                Version.TOOL, m.runId(), m.robotId(), m.sequence(), m.method(), m.seed(), m.labels().site(),
                m.labels().softwareVersion(), m.labels().tags().isEmpty() ? null : m.labels().tags(),
                m.about().domain(), m.about().simulator(), m.about().scenario(),
                m.about().factors().isEmpty() ? null : m.about().factors(), m.about().environment(),
                m.about().modality(), m.about().groundTruth(), m.resources() == null ? null
                        : new PipelineReport.Resources(m.resources().wallTimeS(), m.resources().peakMemoryMib(),
                                m.resources().cpuTimeS(), m.resources().device()), version,
                hash.content(), hash.reference(), hash.estimate(), job.source(), now.toString(), evaluation);
    }
}
