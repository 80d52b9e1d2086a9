package org.trajeval.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.util.ArrayList;
import java.util.Collections;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.pipeline.bundle.ContentHash;
import org.trajeval.pipeline.ledger.Ledger;

/**
 * The report store's group commit under concurrency: for every run, its report is in place and its
 * folder fsync'd before its ledger line is written, both are durable when {@code commit} returns, and
 * each content is reported exactly once with versions 1, 2, 3 ... per run id, however the runs of
 * several threads are grouped.
 */
class GroupCommitOrderTest {
    private static final int THREADS = 8;
    private static final int COMMITS_PER_THREAD = 40;
    private static final int RUN_IDS = 10;
    private static final int CONTENTS_PER_RUN = 3;

    @TempDir
    Path root;

    /** Report files as the service writes them, checking the ledger at each step and pausing in the fsync. */
    private static final class Watched implements ReportFiles {
        final ReportFiles real = ReportFiles.durable();
        final Path ledgerFile;
        final List<String> publishedSinceSync = new ArrayList<>();
        final Map<Staged, String> lineOf = Collections.synchronizedMap(new HashMap<>());
        final List<String> violations = Collections.synchronizedList(new ArrayList<>());

        Watched(Path ledgerFile) {
            this.ledgerFile = ledgerFile;
        }

        @Override
        public Staged stage(Path target, String text) {
            Staged s = real.stage(target, text);
            lineOf.put(s, ledgerLineOf(text));
            return s;
        }

        @Override
        public synchronized void publish(Staged staged) {
            String line = lineOf.remove(staged);
            if (ledgerHas(line)) {
                violations.add("ledger line before the report was in place: " + line);
            }
            real.publish(staged);
            publishedSinceSync.add(line);
        }

        @Override
        public synchronized void syncFolder(Path dir) {
            for (String line : publishedSinceSync) {
                if (ledgerHas(line)) {
                    violations.add("ledger line before the folder's fsync: " + line);
                }
            }
            publishedSinceSync.clear();
            real.syncFolder(dir);
            try {
                Thread.sleep(2); // a slow disk: lets the other threads queue behind this group
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }

        @Override
        public void discard(Staged staged) {
            lineOf.remove(staged);
            real.discard(staged);
        }

        /** @return "RUN_ID<tab>HASH<tab>VERSION" of a report, read from its own fields */
        private static String ledgerLineOf(String reportJson) {
            try {
                JsonNode n = new ObjectMapper().readTree(reportJson);
                return n.get("run_id").asText() + "\t" + n.get("content_sha256").asText() + "\t"
                        + n.get("run_version").asInt();
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }

        private boolean ledgerHas(String runHashVersion) {
            try {
                return Files.exists(ledgerFile) && Files.readString(ledgerFile).contains("\t" + runHashVersion + "\t");
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
    }

    private static JsonNode json(Path report) {
        try {
            return new ObjectMapper().readTree(report.toFile());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    @Test
    void concurrentRunsReportEachContentOnceWithTheReportDurableBeforeItsLedgerLine() throws Exception {
        Path reports = root.resolve("reports");
        Files.createDirectories(reports);
        Path ledgerFile = root.resolve("ledger.tsv");
        Files.writeString(root.resolve("gt.csv"), "t,x,y,yaw\n0,0,0,0\n1,1,0,0\n2,2,0,0\n");
        Files.writeString(root.resolve("est.csv"), "t,x,y,yaw\n0,0,0.1,0\n1,1,0.1,0\n2,2,0.1,0\n");
        EvaluationReport evaluation = new StandInScorer().score(job("probe", "probe"));
        List<String> readingViolations = Collections.synchronizedList(new ArrayList<>());
        Watched files;
        List<Sent> sent = Collections.synchronizedList(new ArrayList<>());
        ReportStore store;
        try (Ledger ledger = Ledger.open(ledgerFile)) {
            files = new Watched(ledgerFile);
            store = ReportStore.withFiles(reports, ledger, Clock.systemUTC(), files);
            ExecutorService pool = Executors.newFixedThreadPool(THREADS);
            List<Future<?>> done = new ArrayList<>();
            for (int t = 0; t < THREADS; t++) {
                int thread = t;
                done.add(pool.submit(() -> {
                    for (int i = 0; i < COMMITS_PER_THREAD; i++) {
                        // every (run, content) is sent several times, by several threads, in different orders
                        int run = (i + thread) % RUN_IDS;
                        String content = "c" + run + "-" + (i / RUN_IDS + thread) % CONTENTS_PER_RUN;
                        RunResult r = store.commit(job("r" + run, "t" + thread + "-" + i),
                                new ContentHash("ref", "est", content), evaluation);
                        // durable when commit returns: the report in place, its ledger line written
                        String line = "\t" + r.runId() + "\t" + content + "\t" + r.version() + "\t";
                        JsonNode rep = json(r.report());
                        if (!content.equals(rep.get("content_sha256").asText()) || rep.get("run_version").asInt() != r.version()) {
                            readingViolations.add("report " + r.report().getFileName() + " is not " + content);
                        }
                        try {
                            if (!Files.readString(ledgerFile).contains(line)) {
                                readingViolations.add("no ledger line when commit returned: " + line.trim());
                            }
                        } catch (IOException e) {
                            throw new UncheckedIOException(e);
                        }
                        sent.add(new Sent(r.runId() + "/" + content, r));
                    }
                }));
            }
            for (Future<?> f : done) {
                f.get(120, TimeUnit.SECONDS);
            }
            pool.shutdown();
        }
        assertEquals(List.of(), files.violations);
        assertEquals(List.of(), readingViolations);

        // exactly once: one REPORTED per (run, content); every DUPLICATE names that report's version
        Map<String, Integer> versionOf = new HashMap<>();
        int reported = 0;
        for (Sent s : sent) {
            if (s.result().outcome() == Outcome.REPORTED) {
                reported++;
                assertEquals(null, versionOf.put(s.content(), s.result().version()), "reported twice: " + s.content());
            }
        }
        assertEquals(RUN_IDS * CONTENTS_PER_RUN, reported);
        assertEquals(THREADS * COMMITS_PER_THREAD, sent.size());
        for (Sent s : sent) {
            assertEquals(versionOf.get(s.content()), s.result().version(), s.content());
        }
        // versions 1..3 per run id, no gap, no repeat; the ledger holds one line per report
        for (int run = 0; run < RUN_IDS; run++) {
            Set<Integer> versions = new HashSet<>();
            for (var e : versionOf.entrySet()) {
                if (e.getKey().startsWith("r" + run + "/")) {
                    versions.add(e.getValue());
                }
            }
            assertEquals(Set.of(1, 2, 3), versions, "versions of r" + run);
        }
        try (Ledger reopened = Ledger.open(ledgerFile)) {
            assertEquals(RUN_IDS * CONTENTS_PER_RUN, reopened.entries().size());
        }
        // no temporary file left, one report file per reported version
        try (var s = Files.list(reports)) {
            assertEquals(RUN_IDS * CONTENTS_PER_RUN, s.count());
        }
        // with eight threads and a slow folder fsync, some runs queue behind a group and commit together
        assertTrue(store.groups() < THREADS * COMMITS_PER_THREAD, store.groups() + " groups");
    }

    /** A run as sent ("RUN_ID/CONTENT") and what its commit returned. */
    private record Sent(String content, RunResult result) {
    }

    private RunJob job(String runId, String source) {
        return new RunJob(RunMetadata.ofName(runId), root.resolve("gt.csv"), root.resolve("est.csv"),
                SettingValues.DEFAULTS, source);
    }
}
