package org.trajeval.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.Callable;
import org.trajeval.core.io.TextFiles;
import org.trajeval.core.protocol.MethodRanking;
import org.trajeval.core.protocol.SuiteAnalysis;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.Comparison;
import org.trajeval.core.report.SuiteReport.RunEntry;
import org.trajeval.core.report.SuiteReportFiles;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code trajeval compare REPORT_A [REPORT_B]}: paired statistics of two methods, from one suite
 * report or from two, over their common evaluated sequences and common seeds.
 */
@Command(name = "compare", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Paired comparison of two methods from suite reports (report.json), with the suite's machinery: "
            + "mean difference per sequence with the t-interval, a seeded bootstrap over sequences, the Wilcoxon "
            + "signed-rank test (Holm family of one test per metric), the Hodges-Lehmann estimate with its interval, "
            + "the share of sequences A wins and the planning figures (--power, --detect).",
            "With one report, name the two methods with -a and -b (not needed when it has exactly two). With two "
                + "reports, -a picks the method of REPORT_A and -b that of REPORT_B (not needed when each has one)."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success", "1:internal error (a bug; rerun with --verbose)",
            "2:bad input (unreadable report, unknown method, nothing in common)"})
public final class CompareCommand implements Callable<Integer> {
    /** Largest suite report read (bytes). */
    static final long MAX_REPORT_BYTES = 1L << 30;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "REPORT_A", description = "Suite report (report.json).")
    Path reportA;

    @Parameters(index = "1", arity = "0..1", paramLabel = "REPORT_B", description = "Second suite report.")
    Path reportB;

    @Option(names = {"-a", "--method-a"}, paramLabel = "NAME", description = "Method A.")
    String methodA;

    @Option(names = {"-b", "--method-b"}, paramLabel = "NAME", description = "Method B.")
    String methodB;

    @Option(names = "--json", description = "Print the comparisons as JSON.")
    boolean json;

    @picocli.CommandLine.Mixin
    StatisticsOptions stats = new StatisticsOptions();

    @Option(names = "--verbose", description = "Print stack traces of errors.")
    boolean verbose;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        SuiteAnalysis.Settings settings = stats.analysis(); // the options before the files
        SuiteReport a = read(reportA);
        SuiteReport b = reportB == null ? a : read(reportB);
        String nameA = pick(a, methodA, reportB == null ? 0 : -1, "-a", reportA);
        String nameB = pick(b, methodB, reportB == null ? 1 : -1, "-b", reportB == null ? reportA : reportB);
        if (reportB == null && nameA.equals(nameB)) {
            throw UsageProblem.of("-b", "-a and -b name the same method", nameA);
        }
        String labelA = nameA;
        String labelB = nameB;
        if (reportB != null && nameA.equals(nameB)) {
            labelA = nameA + "@A";
            labelB = nameB + "@B";
        }
        Set<Long> seeds = new LinkedHashSet<>(a.protocol().seeds().common());
        seeds.retainAll(b.protocol().seeds().common());
        List<String> sequences = new ArrayList<>();
        for (SuiteReport.SequenceEntry s : a.protocol().sequences()) {
            if (a.protocol().evaluatedSplits().contains(s.split()) && b.protocol().sequences().stream().anyMatch(
                    t -> t.id().equals(s.id()) && b.protocol().evaluatedSplits().contains(t.split()))) {
                sequences.add(s.id());
            }
        }
        if (seeds.isEmpty() || sequences.isEmpty()) {
            throw UsageProblem.of("REPORT_B", "the reports have no " + (seeds.isEmpty() ? "seed" : "sequence")
                    + " in common: nothing to pair", null);
        }
        List<RunEntry> runsA = runs(a, nameA, seeds);
        List<RunEntry> runsB = runs(b, nameB, seeds);
        List<String> keys = new ArrayList<>();
        for (SuiteReport.ScoreTerm t : a.protocol().score()) {
            if (b.protocol().score().stream().anyMatch(u -> u.metric().equals(t.metric()))) {
                keys.add(t.metric());
            }
        }
        boolean sameScore = a.protocol().score().equals(b.protocol().score());
        if (sameScore) {
            keys.add(SuiteAnalysis.SCORE);
        }
        for (String k : settings.targets().keySet()) {
            if (!keys.contains(k)) {
                throw UsageProblem.of("--detect", "--detect: the reports have no compared metric '" + k
                        + "'; expected one of " + keys, k);
            }
        }
        List<Comparison> raw = new ArrayList<>();
        for (int i = 0; i < keys.size(); i++) {
            raw.add(SuiteAnalysis.compare(labelA, runsA, labelB, runsB, sequences, keys.get(i), settings, i));
        }
        // the same machinery as the suite: each metric's pairwise tests form one Holm family (here of one test)
        List<Comparison> comparisons = MethodRanking.of(List.of(labelA, labelB), Map.of(labelA, runsA, labelB, runsB),
                sequences, keys, raw, settings.level()).comparisons();
        if (json) {
            out.print(ReportJson.toJson(comparisons));
            out.println();
        } else {
            out.println("A = " + labelA + " (" + reportA + "), B = " + labelB + " ("
                    + (reportB == null ? reportA : reportB) + "); " + sequences.size() + " common sequences, seeds "
                    + seeds);
            if (!sameScore) {
                out.println("score not compared: the two reports define it differently");
            }
            printComparisons(comparisons, stats.confidence, out);
        }
        out.flush();
        return ExitCodes.OK;
    }

    private static List<RunEntry> runs(SuiteReport r, String method, Set<Long> seeds) {
        return r.runs().stream().filter(x -> x.method().equals(method) && seeds.contains(x.seed())).toList();
    }

    private static SuiteReport read(Path p) {
        return SuiteReportFiles.parse(TextFiles.readUtf8(p, "suite report", MAX_REPORT_BYTES), p.toString());
    }

    /** The named method, or the one at {@code index} when unnamed and the report has exactly the methods needed. */
    private static String pick(SuiteReport r, String name, int index, String option, Path source) {
        List<String> names = r.methods().stream().map(SuiteReport.MethodSummary::name).toList();
        if (name != null) {
            if (!names.contains(name)) {
                throw UsageProblem.of(option, source + ": no method '" + name + "' (" + option
                        + "); the report has " + names, null);
            }
            return name;
        }
        if (index < 0 && names.size() == 1) {
            return names.get(0);
        }
        if (index >= 0 && names.size() == 2) {
            return names.get(index);
        }
        throw UsageProblem.of(option, source + ": name the method with " + option + "; the report has " + names,
                null);
    }

    /**
     * Prints one line per comparison, each with its own n, number of non-zero differences and the test
     * (and variant) its conclusion rests on.
     */
    static void printComparisons(List<Comparison> cs, double level, PrintWriter out) {
        String pct = String.format(Locale.ROOT, "%.0f%%", 100 * level);
        out.printf(Locale.ROOT, "%-10s %-10s %-18s %3s %3s %11s %-24s %-24s %-34s %-9s %10s %10s %10s  %s%n", "A", "B",
                "metric", "n", "nz", "mean A-B", "t-interval " + pct, "bootstrap " + pct,
                "Hodges-Lehmann [" + pct + "]", "A better", "Wilcoxon p", "Holm p", "detectable", "test");
        for (Comparison c : cs) {
            SuiteReport.HodgesLehmannEntry hl = c.hodgesLehmann();
            out.printf(Locale.ROOT, "%-10s %-10s %-18s %3d %3d %11s %-24s %-24s %-34s %-9s %10s %10s %10s  %s%n",
                    c.methodA(), c.methodB(), c.metric(), c.n(), c.nonzeroDifferences(),
                    SuiteOutput.num(c.meanDifference()), bounds(c.tInterval()), bounds(c.bootstrap()),
                    hl == null ? "-" : SuiteOutput.num(hl.estimate()) + " " + bounds(new SuiteReport.Bounds(hl.lower(),
                            hl.upper())) + (hl.method().equals("exact") ? "" : " asym"),
                    c.wins() == null ? "-" : c.wins().aBetter() + "/" + c.n(),
                    c.wilcoxon() == null ? "-" : SuiteOutput.num(c.wilcoxon().pValue()),
                    c.holm() == null ? "-" : SuiteOutput.num(c.holm().pAdjusted()),
                    c.planning() == null ? "-" : SuiteOutput.num(c.planning().minDetectableDifference()),
                    c.testLabel());
        }
        if (!cs.isEmpty()) {
            out.println("n: paired sequences; nz: non-zero differences (what the Wilcoxon test ranks); lower is better "
                    + "for error metrics (A-B < 0 favours A), higher for the score; Holm: p adjusted over the metric's "
                    + "pairwise tests; detectable: smallest mean difference detected with "
                    + (cs.get(0).planning() == null ? "80" : String.format(Locale.ROOT, "%.0f",
                            100 * cs.get(0).planning().power())) + "% power; test: what each row's conclusion rests "
                    + "on (report.json and report.html say why)");
            for (Comparison c : cs) {
                if (c.planning() != null && c.planning().targetDifference() != null) {
                    out.printf(Locale.ROOT, "%s vs %s on %s: detecting a mean difference of %s needs %s sequences "
                            + "(s_d = %s)%n", c.methodA(), c.methodB(), c.metric(),
                            c.planning().targetDifference(), c.planning().sequencesNeeded() == null
                                    ? "more than 10^6" : Integer.toString(c.planning().sequencesNeeded()),
                            SuiteOutput.num(c.planning().sdDifference()));
                }
            }
        }
    }

    private static String bounds(SuiteReport.Bounds b) {
        return b == null ? "-" : "[" + SuiteOutput.num(b.lower()) + ", " + SuiteOutput.num(b.upper()) + "]";
    }
}
