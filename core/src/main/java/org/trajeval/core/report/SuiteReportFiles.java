package org.trajeval.core.report;

import org.trajeval.core.InputException;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.trajeval.core.report.SuiteReport.Bounds;
import org.trajeval.core.report.SuiteReport.Comparison;
import org.trajeval.core.report.SuiteReport.MethodSummary;
import org.trajeval.core.report.SuiteReport.MetricSummary;
import org.trajeval.core.report.SuiteReport.RunEntry;

/**
 * Writes a suite report as files: {@code report.json} (the full report), {@code runs.csv} (one row
 * per run), {@code methods.csv} (one row per method) and {@code comparisons.csv} (one row per
 * paired comparison). Everything is deterministic (no timestamps, no absolute paths); numbers are
 * written with {@link Double#toString}, absent values as empty CSV fields / JSON null.
 */
public final class SuiteReportFiles {
    /** File name of the JSON report. */
    public static final String JSON = "report.json";
    /** File name of the per-run table. */
    public static final String RUNS_CSV = "runs.csv";
    /** File name of the per-method table. */
    public static final String METHODS_CSV = "methods.csv";
    /** File name of the comparison table. */
    public static final String COMPARISONS_CSV = "comparisons.csv";

    private static final ObjectMapper READER = org.trajeval.core.io.StrictMappers.json()
            .disable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES);

    private SuiteReportFiles() {
    }

    /** Writes the JSON report and the three CSV tables into {@code dir} (atomically, one by one). */
    public static void write(SuiteReport report, Path dir) {
        ReportJson.writeAtomically(dir.resolve(JSON), toJson(report));
        ReportJson.writeAtomically(dir.resolve(RUNS_CSV), runsCsv(report));
        ReportJson.writeAtomically(dir.resolve(METHODS_CSV), methodsCsv(report));
        ReportJson.writeAtomically(dir.resolve(COMPARISONS_CSV), comparisonsCsv(report));
    }

    /** @return the report as pretty-printed JSON ending in a newline */
    public static String toJson(SuiteReport report) {
        return ReportJson.toJson(report) + "\n";
    }

    /**
     * Parses a {@code report.json}.
     *
     * @throws org.trajeval.core.InputException (UNKNOWN_FORMAT) when the text is not a suite report of a
     *     known schema version
     */
    public static SuiteReport parse(String json, String source) {
        SuiteReport r;
        try {
            com.fasterxml.jackson.databind.JsonNode tree = READER.readTree(json);
            if (tree != null && EvaluationReport.SCHEMA.equals(tree.path("schema").asText(null))) {
                throw InputException.unreadable(source + ": an evaluation report (trajeval eval --out), not a "
                        + "suite report; trajeval res compares evaluation results");
            }
            r = READER.readValue(json, SuiteReport.class);
        } catch (JsonProcessingException e) {
            throw new org.trajeval.core.InputException(source, 0, null, org.trajeval.core.InputProblem.UNKNOWN_FORMAT,
                    "not a suite report: " + e.getOriginalMessage(), null, e);
        }
        if (!SuiteReport.SCHEMA.equals(r.schema())) {
            throw new org.trajeval.core.InputException(source, 0, "schema", org.trajeval.core.InputProblem.UNKNOWN_FORMAT,
                    "not a suite report (schema " + SuiteReport.SCHEMA + " expected)", String.valueOf(r.schema()));
        }
        if (r.schemaVersion() != SuiteReport.SCHEMA_VERSION) {
            throw new org.trajeval.core.InputException(source, 0, "schema_version",
                    org.trajeval.core.InputProblem.UNKNOWN_FORMAT, "suite report schema version "
                    + SuiteReport.SCHEMA_VERSION + " expected", String.valueOf(r.schemaVersion()));
        }
        return r;
    }

    /** @return the per-run table */
    public static String runsCsv(SuiteReport report) {
        List<String> keys = report.protocol().score().stream().map(SuiteReport.ScoreTerm::metric).toList();
        StringBuilder sb = new StringBuilder();
        List<String> header = new ArrayList<>(List.of("method", "sequence", "seed", "split", "status",
                "failure_reason", "failure_detail", "coverage"));
        header.addAll(keys);
        header.addAll(List.of("score", "estimate", "domain", "scenario", "simulator", "environment", "modality",
                "ground_truth", "factors", "budget_status", "wall_time_s", "peak_memory_mib", "real_time_factor",
                "budget_detail"));
        row(sb, header);
        java.util.Map<String, SuiteReport.SequenceEntry> seqs = new java.util.HashMap<>();
        report.protocol().sequences().forEach(s -> seqs.put(s.id(), s));
        java.util.Map<String, BudgetReport.RunBudget> budgets = new java.util.HashMap<>();
        if (report.budgets() != null) {
            report.budgets().runs().forEach(b -> budgets.put(b.method() + "\u0000" + b.sequence() + "\u0000" + b.seed(),
                    b));
        }
        for (RunEntry r : report.runs()) {
            List<String> f = new ArrayList<>(List.of(r.method(), r.sequence(), Long.toString(r.seed()), r.split(),
                    r.status(), r.failure() == null ? "" : r.failure().reason(),
                    r.failure() == null ? "" : r.failure().detail(), num(r.coverage())));
            for (String k : keys) {
                f.add(num(r.metrics() == null ? null : r.metrics().get(k)));
            }
            f.add(num(r.score()));
            f.add(r.estimate());
            SuiteReport.SequenceEntry s = seqs.get(r.sequence());
            boolean known = s != null;
            f.addAll(java.util.Arrays.asList(known ? s.domain() : null, known ? s.scenario() : null,
                    known ? s.simulator() : null, known ? s.environment() : null, known ? s.modality() : null,
                    known ? s.groundTruth() : null, known ? factors(s.factors()) : null));
            BudgetReport.RunBudget b = budgets.get(r.method() + "\u0000" + r.sequence() + "\u0000" + r.seed());
            f.addAll(b == null ? java.util.Arrays.asList("unknown", "", "", "", "") : List.of(b.status(),
                    num(b.wallTimeS()), num(b.peakMemoryMib()), num(b.realTimeFactor()),
                    String.join("; ", b.violations())));
            row(sb, f);
        }
        return sb.toString();
    }

    /** @return the per-method table */
    public static String methodsCsv(SuiteReport report) {
        List<String> keys = report.protocol().score().stream().map(SuiteReport.ScoreTerm::metric).toList();
        StringBuilder sb = new StringBuilder();
        List<String> header = new ArrayList<>(List.of("method", "runs", "failures", "failure_rate",
                "failure_rate_wilson_lower", "failure_rate_wilson_upper", "failure_rate_cp_lower",
                "failure_rate_cp_upper", "failure_rate_clustered_lower", "failure_rate_clustered_upper",
                "failure_rate_clustered_method", "failure_rate_design_effect", "score_mean", "score_sd"));
        for (String k : keys) {
            header.add(k + "_mean_of_sequence_means");
        }
        row(sb, header);
        for (MethodSummary m : report.methods()) {
            List<String> f = new ArrayList<>(List.of(m.name(), Integer.toString(m.runs()),
                    Integer.toString(m.failures())));
            if (m.failureRate() == null) {
                f.addAll(List.of("", "", "", "", "", "", "", "", ""));
            } else {
                f.add(num(m.failureRate().estimate()));
                f.addAll(bounds(m.failureRate().wilson()));
                f.addAll(bounds(m.failureRate().clopperPearson()));
                SuiteReport.ClusteredBounds c = m.failureRate().clustered();
                f.addAll(c == null ? List.of("", "", "", "") : List.of(num(c.lower()), num(c.upper()), c.method(),
                        num(c.designEffect())));
            }
            f.add(num(m.score().mean()));
            f.add(num(m.score().sd()));
            for (String k : keys) {
                MetricSummary ms = m.metrics().stream().filter(x -> x.metric().equals(k)).findFirst().orElse(null);
                f.add(num(ms == null ? null : ms.meanOfSequenceMeans()));
            }
            row(sb, f);
        }
        return sb.toString();
    }

    /** @return the comparison table */
    public static String comparisonsCsv(SuiteReport report) {
        return comparisonsCsv(report.comparisons());
    }

    /** @return the comparison table of these comparisons */
    public static String comparisonsCsv(List<Comparison> comparisons) {
        StringBuilder sb = new StringBuilder();
        row(sb, List.of("method_a", "method_b", "metric", "better", "n", "nonzero_differences", "mean_difference",
                "t_lower", "t_upper", "bootstrap_lower", "bootstrap_upper", "wilcoxon_p", "wilcoxon_method",
                "holm_p", "holm_m", "hodges_lehmann", "hodges_lehmann_lower", "hodges_lehmann_upper",
                "hodges_lehmann_method", "a_better", "ties", "b_better", "share_a_better", "sd_difference",
                "min_detectable_difference", "power", "target_difference", "sequences_needed", "test"));
        for (Comparison c : comparisons) {
            List<String> f = new ArrayList<>(List.of(c.methodA(), c.methodB(), c.metric(), c.better(),
                    Integer.toString(c.n()), Integer.toString(c.nonzeroDifferences()), num(c.meanDifference())));
            f.addAll(bounds(c.tInterval()));
            f.addAll(bounds(c.bootstrap()));
            f.add(c.wilcoxon() == null ? "" : num(c.wilcoxon().pValue()));
            f.add(c.wilcoxon() == null ? "" : c.wilcoxon().method());
            f.add(c.holm() == null ? "" : num(c.holm().pAdjusted()));
            f.add(c.holm() == null ? "" : Integer.toString(c.holm().m()));
            SuiteReport.HodgesLehmannEntry h = c.hodgesLehmann();
            f.addAll(h == null ? List.of("", "", "", "") : List.of(num(h.estimate()), num(h.lower()), num(h.upper()),
                    h.method()));
            SuiteReport.Wins w = c.wins();
            f.addAll(w == null ? List.of("", "", "", "") : List.of(Integer.toString(w.aBetter()),
                    Integer.toString(w.ties()), Integer.toString(w.bBetter()), num(w.shareABetter())));
            SuiteReport.Planning pl = c.planning();
            f.addAll(pl == null ? List.of("", "", "", "", "") : List.of(num(pl.sdDifference()),
                    num(pl.minDetectableDifference()), num(pl.power()), num(pl.targetDifference()),
                    pl.sequencesNeeded() == null ? "" : Integer.toString(pl.sequencesNeeded())));
            f.add(c.test());
            row(sb, f);
        }
        return sb.toString();
    }

    /** @return factor levels as {@code name=level;name=level}, "" without factors */
    private static String factors(java.util.Map<String, Double> f) {
        if (f == null) {
            return "";
        }
        List<String> out = new ArrayList<>();
        new java.util.TreeMap<>(f).forEach((k, v) -> out.add(k + "=" + v));
        return String.join(";", out);
    }

    private static List<String> bounds(Bounds b) {
        return b == null ? List.of("", "") : List.of(num(b.lower()), num(b.upper()));
    }

    private static String num(Double v) {
        return CsvText.number(v);
    }

    private static void row(StringBuilder sb, List<String> fields) {
        CsvText.row(sb, fields);
    }
}
