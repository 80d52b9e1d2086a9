package org.trajeval.core.protocol;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.trajeval.core.report.BudgetReport;
import org.trajeval.core.report.SuiteReport.RunEntry;

/**
 * Checks each run's measured resources against the protocol's budget (lesson section 4: the budget
 * "must be fixed"). With a resources row, the run's achieved real-time factor
 * <pre>
 *   rtf = D / w      D = the reference's duration t_last - t_first (s), w = the run's wall time (s)
 * </pre>
 * must reach the budget's {@code real_time_factor}, its peak memory must not exceed
 * {@code memory_cap_mib}, and a device named in the row must be the budget's. Worked example: a
 * 60 s sequence processed in 240 s has rtf = 0.25, below a budget of 1.0: over budget. A run
 * without a row is "unknown"; a frame-indexed reference (KITTI without times) has no duration, so
 * only memory and device are checked.
 */
public final class BudgetCheck {
    /** Status of a run within the budget. */
    public static final String WITHIN = "within";
    /** Status of a run over the budget. */
    public static final String OVER = "over";
    /** Status of a run without a resources row. */
    public static final String UNKNOWN = "unknown";

    private BudgetCheck() {
    }

    /**
     * @param budget the manifest's budget
     * @param table the measured resources (maybe empty)
     * @param runs every run, in report order
     * @param durationS per sequence id, the reference's duration (s), or null when frame-indexed
     * @return one verdict per run, in the order of {@code runs}
     */
    public static List<BudgetReport.RunBudget> check(Budget budget, ResourcesTable table, List<RunEntry> runs,
            Map<String, Double> durationS) {
        List<BudgetReport.RunBudget> out = new ArrayList<>();
        for (RunEntry r : runs) {
            ResourcesTable.Row row = table.of(r.method(), r.sequence(), r.seed());
            Double d = durationS.get(r.sequence());
            if (row == null) {
                out.add(new BudgetReport.RunBudget(r.method(), r.sequence(), r.seed(), UNKNOWN, null, null, null, null,
                        d, null, List.of()));
                continue;
            }
            List<String> violations = new ArrayList<>();
            Double rtf = d == null || d <= 0.0 ? null : d / row.wallTimeS();
            if (rtf != null && rtf < budget.realTimeFactor()) {
                violations.add("real-time factor " + fig(rtf) + " below the budget's real_time_factor "
                        + budget.realTimeFactor() + " (wall time " + fig(row.wallTimeS()) + " s for " + fig(d)
                        + " s of data)");
            }
            if (row.peakMemoryMib() > budget.memoryCapMib()) {
                violations.add("peak memory " + fig(row.peakMemoryMib()) + " MiB above the budget's memory_cap_mib "
                        + budget.memoryCapMib());
            }
            if (row.device() != null && !row.device().equals(budget.device())) {
                violations.add("ran on " + row.device() + ", the budget's device is " + budget.device());
            }
            out.add(new BudgetReport.RunBudget(r.method(), r.sequence(), r.seed(),
                    violations.isEmpty() ? WITHIN : OVER, row.wallTimeS(), row.peakMemoryMib(), row.cpuTimeS(),
                    row.device(), d, rtf, violations));
        }
        return out;
    }

    /**
     * The budget section, and the runs with the policy applied: with {@code fail}, a successful run
     * over the budget becomes a failed run of reason {@code budget} (score 0, its metrics kept); with
     * {@code warn} it stays as it is and is named in a warning. A run that failed for another reason
     * keeps that reason (its budget verdict is still in the section).
     *
     * @param checked the section, the runs to report and the warnings
     */
    public record Applied(BudgetReport report, List<RunEntry> runs, List<String> warnings) {
    }

    /** Checks every run and applies the manifest's policy (see {@link Applied}). */
    public static Applied apply(SuiteManifest m, ResourcesTable table, List<RunEntry> runs,
            Map<String, Double> durationS) {
        List<BudgetReport.RunBudget> verdicts = check(m.budget(), table, runs, durationS);
        boolean fail = m.failure().budget() == FailureDefinition.BudgetPolicy.FAIL;
        List<RunEntry> out = new ArrayList<>();
        List<String> over = new ArrayList<>();
        int unknown = 0;
        for (int i = 0; i < runs.size(); i++) {
            RunEntry r = runs.get(i);
            BudgetReport.RunBudget v = verdicts.get(i);
            if (v.status().equals(UNKNOWN)) {
                unknown++;
            }
            if (v.status().equals(OVER)) {
                over.add(r.method() + "/" + r.sequence() + "/seed " + r.seed() + ": " + String.join("; ",
                        v.violations()));
                if (fail && r.ok()) {
                    r = new RunEntry(r.method(), r.sequence(), r.seed(), r.split(), r.estimate(), "failed",
                            new org.trajeval.core.report.SuiteReport.RunFailure("budget", String.join("; ",
                                    v.violations())), r.coverage(), r.metrics(), 0.0, r.evaluation());
                }
            }
            out.add(r);
        }
        List<String> warnings = new ArrayList<>();
        if (!over.isEmpty()) {
            warnings.add("BUDGET: " + over.size() + " run(s) over the budget (" + (fail ? "failed, failure.budget: fail"
                    : "kept, failure.budget: warn") + "): " + String.join(" | ", over.subList(0, Math.min(3,
                    over.size()))) + (over.size() > 3 ? " | and " + (over.size() - 3) + " more" : ""));
        }
        if (m.resources() != null && unknown > 0) {
            warnings.add("BUDGET: " + unknown + " run(s) have no row in " + m.resources() + ": budget unknown");
        }
        List<String> names = m.methods().stream().map(MethodSpec::name).toList();
        BudgetReport report = new BudgetReport(m.resources(), fail ? "fail" : "warn", unknown, perMethod(names,
                verdicts), verdicts);
        return new Applied(report, out, warnings);
    }

    /** @return v to 4 significant digits without trailing zeros (0.25, 240, 2048) */
    static String fig(double v) {
        return new java.math.BigDecimal(String.format(Locale.ROOT, "%.4g", v)).stripTrailingZeros().toPlainString();
    }

    /** @return per method (in the order of {@code methods}): runs, within, over, unknown and compliance */
    public static List<BudgetReport.MethodBudget> perMethod(List<String> methods, List<BudgetReport.RunBudget> runs) {
        Map<String, int[]> counts = new LinkedHashMap<>();
        methods.forEach(m -> counts.put(m, new int[3]));
        for (BudgetReport.RunBudget r : runs) {
            int[] c = counts.get(r.method());
            c[r.status().equals(WITHIN) ? 0 : r.status().equals(OVER) ? 1 : 2]++;
        }
        List<BudgetReport.MethodBudget> out = new ArrayList<>();
        counts.forEach((m, c) -> out.add(new BudgetReport.MethodBudget(m, c[0] + c[1] + c[2], c[0], c[1], c[2],
                c[0] + c[1] == 0 ? null : c[0] / (double) (c[0] + c[1]))));
        return out;
    }
}
