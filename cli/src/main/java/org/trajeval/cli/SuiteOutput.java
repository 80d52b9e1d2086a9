package org.trajeval.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.trajeval.core.protocol.RunEngine;
import org.trajeval.core.protocol.SuiteRunner;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReportFiles;
import org.trajeval.figures.SuiteReportFolder;
import org.trajeval.store.Labels;
import org.trajeval.store.ReportRecords;
import org.trajeval.store.ResultsStore;

/** Runs a suite and writes its report folder; shared by {@code suite} and {@code demo}. */
final class SuiteOutput {
    private SuiteOutput() {
    }

    /** Runs the manifest with {@code threads} workers and writes report.json, the CSV tables and report.html. */
    static SuiteReport runAndWrite(Path manifest, Path out, SuiteRunner.Settings settings, int threads,
            PrintWriter err) {
        if (threads < 1) {
            throw UsageProblem.of("--threads", "--threads must be at least 1", String.valueOf(threads));
        }
        SuiteReportFolder.refuseToReplaceInputs(manifest, out, "--out");
        ExecutorService pool = Executors.newFixedThreadPool(threads);
        try {
            SuiteRunner.Result result = new SuiteRunner(RunEngine.standard(), pool, ProgressBar.forTerminal(err))
                    .run(manifest, settings);
            SuiteReportFolder.write(result, out);
            return result.report();
        } finally {
            pool.shutdownNow();
        }
    }

    /** Prints the hygiene warnings, the method table and the score comparisons. */
    static void printSummary(SuiteReport r, PrintWriter out) {
        for (String w : r.hygiene().warnings()) {
            out.println("WARNING: " + w);
        }
        List<String> keys = r.protocol().score().stream().map(SuiteReport.ScoreTerm::metric).toList();
        StringBuilder head = new StringBuilder(String.format(Locale.ROOT, "%-12s %5s %5s %-24s %-16s %-16s",
                "method", "runs", "fail", "failure rate [Wilson]", "clustered [K-G]", "score (sd)"));
        for (String k : keys) {
            head.append(String.format(Locale.ROOT, " %18s", k));
        }
        out.println(head);
        for (SuiteReport.MethodSummary m : r.methods()) {
            String rate = m.failureRate() == null ? "-" : String.format(Locale.ROOT, "%.3f [%.3f, %.3f]",
                    m.failureRate().estimate(), m.failureRate().wilson().lower(), m.failureRate().wilson().upper());
            SuiteReport.ClusteredBounds cl = m.failureRate() == null ? null : m.failureRate().clustered();
            String clustered = cl == null ? "-" : String.format(Locale.ROOT, "[%.3f, %.3f]", cl.lower(), cl.upper());
            StringBuilder line = new StringBuilder(String.format(Locale.ROOT, "%-12s %5d %5d %-24s %-16s %-16s",
                    m.name(), m.runs(), m.failures(), rate, clustered,
                    num(m.score().mean()) + " (" + num(m.score().sd()) + ")"));
            for (String k : keys) {
                SuiteReport.MetricSummary ms = m.metrics().stream().filter(x -> x.metric().equals(k)).findFirst()
                        .orElse(null);
                line.append(String.format(Locale.ROOT, " %18s", ms == null ? "-" : num(ms.meanOfSequenceMeans())));
            }
            out.println(line);
        }
        out.println();
        out.println("failure rate: [Wilson] treats every run as independent; [K-G] treats the seeds of one sequence "
                + "as a cluster (Korn-Graubard), the interval to quote");
        out.println();
        CompareCommand.printComparisons(r.comparisons(), r.protocol().analysis().confidenceLevel(), out);
        printRankings(r.rankings(), out);
        SimRealOutput.print(r, out);
    }

    /** Prints, per metric, the Friedman and Iman-Davenport tests, the average ranks and the groups. */
    static void printRankings(List<SuiteReport.Ranking> rankings, PrintWriter out) {
        if (rankings == null || rankings.isEmpty()) {
            return;
        }
        out.println();
        out.println("all methods at once (rank 1 = best; groups: no pair differs after Holm over the metric's "
                + "pairwise Wilcoxon tests):");
        for (SuiteReport.Ranking k : rankings) {
            if (k.friedman() == null) {
                out.printf(Locale.ROOT, "%-18s not ranked: %d sequence(s) where every method has a value%n", k.metric(),
                        k.n());
                continue;
            }
            StringBuilder ranks = new StringBuilder();
            k.methods().stream().sorted(java.util.Comparator.comparingDouble(SuiteReport.RankedMethod::averageRank))
                    .forEach(m -> ranks.append(String.format(Locale.ROOT, " %s %.2f", m.name(), m.averageRank())));
            out.printf(Locale.ROOT, "%-18s n = %d  Friedman chi2 = %s p = %s  Iman-Davenport F = %s p = %s  ranks:%s"
                    + "  groups: %s%n", k.metric(), k.n(), num(k.friedman().statistic()),
                    num(k.friedman().pValue()), k.imanDavenport().statistic() == null ? "inf"
                            : num(k.imanDavenport().statistic()), num(k.imanDavenport().pValue()), ranks,
                    k.groups().isEmpty() ? "none (every pair differs)" : k.groups().toString());
        }
    }

    /** Records a suite's runs in the results store, after its report files (the source of truth). */
    static void record(SuiteReport r, Path reportDir, Labels labels, StoreOptions store,
            PrintWriter o) {
        try (ResultsStore s = store.open()) {
            int n = s.record(ReportRecords.fromSuite(r,
                    reportDir.resolve(SuiteReportFiles.JSON).toString(),
                    Instant.now(), labels));
            o.printf(Locale.ROOT, "recorded %d new run(s) of %d in %s%n", n, r.runs().size(), s.location());
        }
    }

    static String num(Double v) {
        return v == null ? "-" : String.format(Locale.ROOT, "%.4g", v);
    }
}
