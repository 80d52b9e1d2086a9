package org.trajeval.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import org.trajeval.core.protocol.RegressionGate;
import org.trajeval.core.protocol.RegressionGate.Finding;
import org.trajeval.core.protocol.RegressionGate.Verdict;
import org.trajeval.core.protocol.SuiteAnalysis;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReportFiles;
import org.trajeval.store.GatePairing;
import org.trajeval.store.ResultsStore;
import org.trajeval.store.Selection;
import org.trajeval.store.StoredGate;
import org.trajeval.store.StoredMetric;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code trajeval gate BASELINE CANDIDATE}: fails (exit 5) when a method of the candidate is worse
 * than the same method of the baseline beyond a tolerance, with the chosen confidence.
 */
@Command(name = "gate", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Regression gate for CI: compares each method of the candidate with the same-named method "
            + "of the baseline, runs paired by (sequence, seed), with the suite's paired statistics.",
            "A metric regresses when the one-sided bound of the mean paired difference (candidate - baseline, "
                + "per sequence, means over the common seeds; the less favourable of the t-interval and the "
                + "bootstrap over sequences) is worse than tolerance x |baseline mean|; the k gated (method, metric) "
                + "pairs share --confidence (Bonferroni: each at 1 - (1 - C) / k).",
            "BASELINE and CANDIDATE are suite reports (report.json or its folder); or, with --db, "
                + "--baseline and --candidate select stored runs (e.g. software_version=2.3)."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:no metric regressed beyond its tolerance", "1:internal error (a bug; rerun with --verbose)",
            "2:bad input (unreadable report or store, unknown metric, nothing to pair)",
            "5:a metric regressed beyond its tolerance"})
public final class GateCommand implements Callable<Integer> {
    /** The default tolerance of every gated metric (5 %). */
    static final double DEFAULT_TOLERANCE = 0.05;

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "BASELINE", description = "Baseline suite report.")
    Path baselinePath;

    @Parameters(index = "1", arity = "0..1", paramLabel = "CANDIDATE", description = "Candidate suite report.")
    Path candidatePath;

    @Option(names = "--max-regression", paramLabel = "METRIC=PCT",
            description = {"Tolerance of a metric in percent of the baseline, e.g. ate_trans_rmse_m=5 (repeatable).",
                "Default: every score metric of the reports at 5 % (with --db: ate_trans_rmse_m and "
                    + "rpe_trans_rmse_m at 5 %). Metrics: the score metrics, coverage, score."})
    List<String> maxRegression = new ArrayList<>();

    @Option(names = "--confidence", paramLabel = "C", defaultValue = "0.95",
            description = "One-sided confidence of a regression, in (0.5, 1) (default: ${DEFAULT-VALUE}).")
    double confidence;

    @Option(names = "--markdown", paramLabel = "FILE", description = "Write a Markdown summary (merge-request comment).")
    Path markdown;

    @Option(names = "--junit", paramLabel = "FILE", description = "Write JUnit XML (one test case per method, "
            + "metric and sequence).")
    Path junit;

    @Mixin
    StoreOptions store = new StoreOptions();

    @Option(names = "--baseline", paramLabel = "SELECTION", description = "With --db: the baseline runs, "
            + "KEY=VALUE[,KEY=VALUE...] over robot, site, route, method, version, dataset or a free tag.")
    String baselineSelection;

    @Option(names = "--candidate", paramLabel = "SELECTION", description = "With --db: the candidate runs.")
    String candidateSelection;

    @Option(names = "--pair-by", paramLabel = "KEY", defaultValue = "route-seed",
            converter = PairByConverter.class,
            description = "With --db: pair runs by route-seed or robot-route (default: ${DEFAULT-VALUE}).")
    GatePairing pairBy;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1", description = "Bootstrap seed (default: ${DEFAULT-VALUE}).")
    long seed;

    @Option(names = "--resamples", paramLabel = "B", defaultValue = "4000",
            description = "Bootstrap resamples (default: ${DEFAULT-VALUE}).")
    int resamples;

    @Option(names = "--verbose", description = "Print stack traces of errors.")
    boolean verbose;

    /** The findings, how many sequences the baseline has, and the two sides' names. */
    private record Gated(List<Finding> findings, int sequences, String baselineName, String candidateName) {
    }

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        RegressionGate.Settings settings = new RegressionGate.Settings(confidence, seed, resamples);
        Gated sides = store.given() ? fromStore(settings) : fromFiles(err, settings);
        List<Finding> findings = sides.findings();
        if (findings.stream().allMatch(f -> f.n() == 0)) {
            throw UsageProblem.of("gate: baseline and candidate have no (sequence, seed) in common: "
                    + "nothing to pair");
        }
        out.println("baseline " + sides.baselineName() + ", candidate " + sides.candidateName() + "; "
                + sides.sequences() + " sequences");
        GateOutput.table(findings, confidence, out);
        out.flush();
        java.util.List<Path> inputs = new java.util.ArrayList<>();
        for (Path p : new Path[] {baselinePath, candidatePath}) {
            if (p != null) {
                inputs.add(p);
                inputs.add(p.resolve("report.json"));
            }
        }
        if (markdown != null) {
            org.trajeval.core.io.OutputGuard.refuseInputs(markdown, "--markdown", inputs);
        }
        if (junit != null) {
            org.trajeval.core.io.OutputGuard.refuseInputs(junit, "--junit", inputs);
        }
        if (markdown != null) {
            ReportJson.writeAtomically(markdown, GateOutput.markdown(findings, confidence, sides.baselineName(),
                    sides.candidateName()));
        }
        if (junit != null) {
            ReportJson.writeAtomically(junit, GateOutput.junit(findings));
        }
        return findings.stream().anyMatch(f -> f.verdict() == Verdict.REGRESSION) ? ExitCodes.REGRESSION
                : ExitCodes.OK;
    }

    private Gated fromFiles(PrintWriter err, RegressionGate.Settings settings) {
        if (baselinePath == null || candidatePath == null) {
            throw UsageProblem.of("gate: give BASELINE and CANDIDATE suite reports, or --db with "
                    + "--baseline and --candidate");
        }
        if (baselineSelection != null || candidateSelection != null) {
            throw UsageProblem.of("gate: --baseline and --candidate select stored runs: they need --db");
        }
        SuiteReport b = read(baselinePath);
        SuiteReport c = read(candidatePath);
        List<String> sequences = new ArrayList<>();
        for (SuiteReport.SequenceEntry s : b.protocol().sequences()) {
            if (b.protocol().evaluatedSplits().contains(s.split()) && c.protocol().sequences().stream().anyMatch(
                    t -> t.id().equals(s.id()) && c.protocol().evaluatedSplits().contains(t.split()))) {
                sequences.add(s.id());
            }
        }
        List<String> baseMethods = b.methods().stream().map(SuiteReport.MethodSummary::name).toList();
        List<String> methods = new ArrayList<>();
        for (SuiteReport.MethodSummary m : c.methods()) {
            if (baseMethods.contains(m.name())) {
                methods.add(m.name());
            } else {
                err.println("note: method " + m.name() + " of the candidate is not in the baseline: not gated");
            }
        }
        if (methods.isEmpty()) {
            throw UsageProblem.of("gate: the candidate has no method of the baseline " + baseMethods);
        }
        List<String> metrics = new ArrayList<>();
        for (SuiteReport.ScoreTerm t : b.protocol().score()) {
            if (c.protocol().score().stream().anyMatch(u -> u.metric().equals(t.metric()))) {
                metrics.add(t.metric());
            }
        }
        err.flush();
        List<Finding> findings = RegressionGate.gateAll(b.runs(), c.runs(), methods, sequences, tolerances(metrics),
                settings);
        return new Gated(findings, sequences.size(), baselinePath.toString(), candidatePath.toString());
    }

    private Gated fromStore(RegressionGate.Settings settings) {
        if (baselinePath != null || candidatePath != null) {
            throw UsageProblem.of("gate: with --db, select the two sides with --baseline and "
                    + "--candidate instead of report files");
        }
        if (baselineSelection == null || candidateSelection == null) {
            throw UsageProblem.of("gate: --db needs --baseline SELECTION and --candidate SELECTION "
                    + "(e.g. software_version=2.3)");
        }
        Selection bs = Selection.parse(baselineSelection, "--baseline");
        Selection cs = Selection.parse(candidateSelection, "--candidate");
        Map<String, Double> tolerances = tolerances(List.of("ate_trans_rmse_m", "rpe_trans_rmse_m"));
        StoredGate.Result r;
        try (ResultsStore s = store.open()) {
            r = StoredGate.gate(s, bs, cs, pairBy, tolerances, settings);
        }
        return new Gated(r.findings(), r.baselineSequences(), "--baseline " + bs, "--candidate " + cs);
    }

    private Map<String, Double> tolerances(List<String> defaults) {
        Map<String, Double> t = new LinkedHashMap<>();
        if (maxRegression.isEmpty()) {
            defaults.forEach(m -> t.put(m, DEFAULT_TOLERANCE));
            return t;
        }
        for (String spec : maxRegression) {
            int eq = spec.indexOf('=');
            String metric = eq < 0 ? spec : spec.substring(0, eq);
            if (!StoredMetric.keys().contains(metric)) {
                throw UsageProblem.of("--max-regression: expected METRIC=PCT with METRIC one of "
                        + String.join(", ", StoredMetric.keys()) + ", found \"" + spec + "\"");
            }
            double pct;
            try {
                pct = eq < 0 ? Double.NaN : Double.parseDouble(spec.substring(eq + 1).replace("%", "").strip());
            } catch (NumberFormatException e) {
                pct = Double.NaN;
            }
            if (!(pct >= 0 && pct < 1e6)) {
                throw UsageProblem.of("--max-regression: expected METRIC=PCT with PCT a percentage >= 0 "
                        + "(e.g. ate_trans_rmse_m=5), found \"" + spec + "\"");
            }
            t.put(metric.equals("score") ? SuiteAnalysis.SCORE : metric, pct / 100.0);
        }
        return t;
    }

    private static SuiteReport read(Path p) {
        Path file = Files.isDirectory(p) ? p.resolve(SuiteReportFiles.JSON) : p;
        try {
            return SuiteReportFiles.parse(Files.readString(file), file.toString());
        } catch (IOException e) {
            throw new UncheckedIOException("could not read " + file + " (" + e.getClass().getSimpleName() + ")", e);
        }
    }

    /** route-seed|robot-route. */
    static final class PairByConverter implements picocli.CommandLine.ITypeConverter<GatePairing> {
        @Override
        public GatePairing convert(String v) {
            return EnumWords.parse(GatePairing.class, v, "route-seed|robot-route");
        }
    }
}
