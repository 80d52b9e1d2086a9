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
import java.util.Set;
import java.util.concurrent.Callable;
import org.trajeval.core.io.TextFiles;
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
        description = {"Paired comparison of two methods from suite reports (report.json): mean difference per "
            + "sequence with the t-interval, a seeded bootstrap over sequences and the Wilcoxon signed-rank test.",
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
        SuiteReport a = read(reportA);
        SuiteReport b = reportB == null ? a : read(reportB);
        String nameA = pick(a, methodA, reportB == null ? 0 : -1, "-a", reportA);
        String nameB = pick(b, methodB, reportB == null ? 1 : -1, "-b", reportB == null ? reportA : reportB);
        if (reportB == null && nameA.equals(nameB)) {
            throw new IllegalArgumentException("-a and -b name the same method: " + nameA);
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
            throw new IllegalArgumentException("the reports have no " + (seeds.isEmpty() ? "seed" : "sequence")
                    + " in common: nothing to pair");
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
        SuiteAnalysis.Settings settings = new SuiteAnalysis.Settings(stats.seed, stats.confidence, stats.resamples);
        List<Comparison> comparisons = new ArrayList<>();
        for (int i = 0; i < keys.size(); i++) {
            comparisons.add(SuiteAnalysis.compare(labelA, runsA, labelB, runsB, sequences, keys.get(i), settings, i));
        }
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
                throw new IllegalArgumentException(source + ": no method '" + name + "' (" + option
                        + "); the report has " + names);
            }
            return name;
        }
        if (index < 0 && names.size() == 1) {
            return names.get(0);
        }
        if (index >= 0 && names.size() == 2) {
            return names.get(index);
        }
        throw new IllegalArgumentException(source + ": name the method with " + option + "; the report has " + names);
    }

    /** Prints one line per comparison. */
    static void printComparisons(List<Comparison> cs, double level, PrintWriter out) {
        String pct = String.format(Locale.ROOT, "%.0f%%", 100 * level);
        out.printf(Locale.ROOT, "%-10s %-10s %-18s %3s %11s %-24s %-24s %10s%n", "A", "B", "metric", "n", "mean A-B",
                "t-interval " + pct, "bootstrap " + pct, "Wilcoxon p");
        for (Comparison c : cs) {
            out.printf(Locale.ROOT, "%-10s %-10s %-18s %3d %11s %-24s %-24s %10s%n", c.methodA(), c.methodB(),
                    c.metric(), c.n(), SuiteOutput.num(c.meanDifference()), bounds(c.tInterval()),
                    bounds(c.bootstrap()), c.wilcoxon() == null ? "-" : SuiteOutput.num(c.wilcoxon().pValue())
                            + (c.wilcoxon().method().equals("exact") ? "" : "*"));
        }
        if (!cs.isEmpty()) {
            out.println("which test applies (n = " + cs.get(0).n() + "): " + cs.get(0).primary());
            out.println("lower is better for error metrics (A-B < 0 favours A); higher is better for the score."
                    + (cs.stream().anyMatch(c -> c.wilcoxon() != null && !c.wilcoxon().method().equals("exact"))
                            ? " * normal approximation" : ""));
        }
    }

    private static String bounds(SuiteReport.Bounds b) {
        return b == null ? "-" : "[" + SuiteOutput.num(b.lower()) + ", " + SuiteOutput.num(b.upper()) + "]";
    }
}
