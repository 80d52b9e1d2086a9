package org.trajeval.cli;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.report.BudgetReport;
import org.trajeval.core.report.DomainGapReport;
import org.trajeval.core.report.FactorSweep;
import org.trajeval.core.report.SliceReport;
import org.trajeval.core.report.SuiteReport;

/** Terminal lines of a suite's domain gap, stress sweeps, budget check and slices. */
final class SimRealOutput {
    private SimRealOutput() {
    }

    /** Prints every section the report has (nothing for a suite without them). */
    static void print(SuiteReport r, PrintWriter out) {
        gap(r.domainGap(), out);
        sweeps(r.factorSweeps(), out);
        budgets(r.budgets(), out);
        slices(r.slices(), out);
    }

    private static void gap(DomainGapReport g, PrintWriter out) {
        if (g == null) {
            return;
        }
        out.println();
        out.printf(Locale.ROOT, "domain gap: Delta_gap = L_real - L_sim over %d sim and %d real sequences; %s "
                + "bootstrap %s (%s)%n", g.simSequences().size(), g.realSequences().size(), pct(g.level()),
                g.intervalMethod(), g.intervalReason());
        out.printf(Locale.ROOT, "%-18s %-12s %10s %10s %-30s %8s %9s%n", "metric", "method", "L_sim", "L_real",
                "gap [" + pct(g.level()) + "]", "rank sim", "rank real");
        for (DomainGapReport.MetricGap m : g.metrics()) {
            for (DomainGapReport.MethodGap x : m.methods()) {
                out.printf(Locale.ROOT, "%-18s %-12s %10s %10s %-30s %8s %9s%n", m.metric(), x.method(), num(x.lSim()),
                        num(x.lReal()), num(x.gap()) + " " + bounds(x.gapInterval()), rank(x.rankSim()),
                        rank(x.rankReal()));
            }
            out.printf(Locale.ROOT, "%-18s Kendall tau between the sim and the real ranking: %s%n", m.metric(),
                    num(m.kendallTau()));
            for (DomainGapReport.Flip f : m.flips()) {
                out.printf(Locale.ROOT, "FLIP %s: %s is better in sim, %s in real; gap %s - gap %s = %s %s; %s "
                        + "(sim: %s, real: %s)%n", m.metric(), f.betterInSim(), f.betterInReal(), f.methodA(),
                        f.methodB(), num(f.gapDifference()), bounds(f.gapDifferenceInterval()),
                        f.supported() ? "supported by the paired comparisons on both sides"
                                : "not supported on both sides", side(f.sim()), side(f.real()));
            }
        }
    }

    private static String side(DomainGapReport.Side s) {
        return s.test() + (s.wilcoxonP() == null ? "" : " p = " + num(s.wilcoxonP())) + " on " + s.n()
                + (s.supports() ? ", finds the order" : ", does not find the order");
    }

    private static void sweeps(List<FactorSweep> sweeps, PrintWriter out) {
        if (sweeps == null) {
            return;
        }
        for (FactorSweep s : sweeps) {
            out.println();
            out.printf(Locale.ROOT, "stress sweep '%s' over %d sequences (breakdown: failure rate >= %s; report.json "
                    + "also has the interval clustered by sequence):%n", s.factor(), s.sequences().size(),
                    num(s.breakdownRate()));
            String metric = s.methods().isEmpty() || s.methods().get(0).levels().isEmpty() ? "-"
                    : s.methods().get(0).levels().get(0).metrics().get(0).metric();
            out.printf(Locale.ROOT, "%-12s %8s %5s %-26s %-34s%n", "method", "level", "runs", "failure rate [Wilson]",
                    metric + " median [interval]");
            for (FactorSweep.MethodSweep m : s.methods()) {
                for (FactorSweep.Level l : m.levels()) {
                    SuiteReport.Proportion p = l.failureRate();
                    String rate = p == null ? "-" : String.format(Locale.ROOT, "%.3f [%.3f, %.3f]", p.estimate(),
                            p.wilson().lower(), p.wilson().upper());
                    FactorSweep.LevelMetric lm = l.metrics().get(0);
                    out.printf(Locale.ROOT, "%-12s %8s %5d %-26s %-34s%n", m.method(), num(l.level()), l.runs(), rate,
                            lm.median() == null ? "-" : num(lm.median()) + " [" + num(lm.lower()) + ", "
                                    + num(lm.upper()) + "]");
                }
                out.printf(Locale.ROOT, "%-12s breakdown level: %s; Kendall tau of %s with the level: %s%n",
                        m.method(), m.breakdownLevel() == null ? "none" : num(m.breakdownLevel()), metric,
                        m.sensitivity().isEmpty() ? "-" : num(m.sensitivity().get(0).kendallTau()));
            }
        }
    }

    private static void budgets(BudgetReport b, PrintWriter out) {
        if (b == null || b.resources() == null) {
            return;
        }
        out.println();
        out.printf(Locale.ROOT, "budget (%s, policy %s; %d run(s) unknown):%n", b.resources(), b.policy(),
                b.unknownRuns());
        out.printf(Locale.ROOT, "%-12s %5s %7s %5s %8s %11s%n", "method", "runs", "within", "over", "unknown",
                "compliance");
        for (BudgetReport.MethodBudget m : b.methods()) {
            out.printf(Locale.ROOT, "%-12s %5d %7d %5d %8d %11s%n", m.method(), m.runs(), m.within(), m.over(),
                    m.unknown(), num(m.compliance()));
        }
        for (BudgetReport.RunBudget r : b.runs()) {
            if (r.status().equals("over")) {
                out.printf(Locale.ROOT, "OVER BUDGET %s/%s/seed %d: %s%n", r.method(), r.sequence(), r.seed(),
                        String.join("; ", r.violations()));
            }
        }
    }

    private static void slices(List<SliceReport> slices, PrintWriter out) {
        if (slices == null || slices.isEmpty()) {
            return;
        }
        out.println();
        out.println("slices (score mean and failures per method on the slice's sequences):");
        for (SliceReport s : slices) {
            List<String> cells = new ArrayList<>();
            for (SuiteReport.MethodSummary m : s.methods()) {
                cells.add(m.name() + " " + num(m.score().mean()) + " (" + m.failures() + "/" + m.runs() + " failed)");
            }
            out.printf(Locale.ROOT, "%-24s %2d seq  %s%n", s.dimension() + "=" + s.value(), s.sequences().size(),
                    String.join("  ", cells));
        }
    }

    private static String rank(Double r) {
        return r == null ? "-" : String.format(Locale.ROOT, "%.1f", r);
    }

    private static String pct(double level) {
        return String.format(Locale.ROOT, "%.0f %%", level * 100);
    }

    private static String num(Double v) {
        return SuiteOutput.num(v);
    }

    private static String bounds(SuiteReport.Bounds b) {
        return b == null ? "[-]" : "[" + num(b.lower()) + ", " + num(b.upper()) + "]";
    }
}
