package org.trajeval.figures;

import static org.trajeval.figures.SuiteHtml.bounds;
import static org.trajeval.figures.SuiteHtml.esc;
import static org.trajeval.figures.SuiteHtml.fmt;
import static org.trajeval.figures.SuiteHtml.pct;

import java.util.List;
import java.util.Map;
import org.trajeval.core.report.BudgetReport;
import org.trajeval.core.report.DomainGapReport;
import org.trajeval.core.report.FactorSweep;
import org.trajeval.core.report.SliceReport;
import org.trajeval.core.report.SuiteReport;

/**
 * The report page's sections on simulation beside reality: the domain gap with its flips, the
 * stress sweeps (table and figures), the budget check and the slices. Each is left out when the
 * report has no such data.
 */
final class SimRealHtml {
    private SimRealHtml() {
    }

    static void sections(StringBuilder h, SuiteReport r, Map<Figure, String> svg) {
        gap(h, r.domainGap());
        sweeps(h, r.factorSweeps(), svg);
        budgets(h, r.budgets());
        slices(h, r.slices());
    }

    private static void gap(StringBuilder h, DomainGapReport g) {
        if (g == null) {
            return;
        }
        h.append("<h2>Simulation beside reality: domain gap</h2>\n<p class=\"small\">Delta<sub>gap</sub> = L<sub>real")
                .append("</sub> - L<sub>sim</sub>, each L the mean over the domain's sequences of the per-sequence ")
                .append("means over seeds (lesson section 8). ").append(g.simSequences().size()).append(" sim and ")
                .append(g.realSequences().size()).append(" real sequences; interval: ").append(pct(g.level()))
                .append(" percentile bootstrap, <code>").append(esc(g.intervalMethod())).append("</code> (")
                .append(esc(g.intervalReason())).append("). Rank 1 = best.</p>\n");
        for (DomainGapReport.MetricGap m : g.metrics()) {
            String unit = m.metric().equals("score") ? "score S" : esc(MetricLabel.of(m.metric()).label());
            h.append("<h3>").append(unit).append(" <span class=\"small\">(").append(esc(m.metric()))
                    .append(", Kendall &tau; between the rankings ").append(fmt(m.kendallTau())).append(")</span></h3>\n")
                    .append("<table><thead><tr><th class=\"l\">method</th><th>L<sub>sim</sub></th><th>L<sub>real</sub>")
                    .append("</th><th>gap</th><th>gap ").append(pct(g.level())).append("</th><th>rank sim</th>")
                    .append("<th>rank real</th></tr></thead><tbody>\n");
            for (DomainGapReport.MethodGap x : m.methods()) {
                h.append("<tr><td class=\"l\">").append(esc(x.method())).append("</td><td>").append(fmt(x.lSim()))
                        .append("</td><td>").append(fmt(x.lReal())).append("</td><td>").append(fmt(x.gap()))
                        .append("</td><td>").append(bounds(x.gapInterval())).append("</td><td>")
                        .append(fmt(x.rankSim())).append("</td><td>").append(fmt(x.rankReal())).append("</td></tr>\n");
            }
            h.append("</tbody></table>\n");
            for (DomainGapReport.Flip f : m.flips()) {
                h.append("<div class=\"").append(f.supported() ? "bad" : "warn").append("\">Ranking flip: <b>")
                        .append(esc(f.betterInSim())).append("</b> is better in simulation, <b>")
                        .append(esc(f.betterInReal())).append("</b> in reality. Gap difference ")
                        .append(esc(f.methodA())).append(" - ").append(esc(f.methodB())).append(" = ")
                        .append(fmt(f.gapDifference())).append(" ").append(bounds(f.gapDifferenceInterval()))
                        .append("; ").append(f.supported() ? "supported by the paired comparisons on both sides"
                                : "not supported on both sides").append(" (sim: ").append(side(f.sim()))
                        .append("; real: ").append(side(f.real())).append(").</div>\n");
            }
        }
    }

    private static String side(DomainGapReport.Side s) {
        return esc(s.test()) + ", n = " + s.n() + (s.wilcoxonP() == null ? "" : ", Wilcoxon p = " + fmt(s.wilcoxonP()))
                + (s.supports() ? ", finds the order" : ", does not find the order");
    }

    private static void sweeps(StringBuilder h, List<FactorSweep> sweeps, Map<Figure, String> svg) {
        if (sweeps == null || sweeps.isEmpty()) {
            return;
        }
        h.append("<h2>Stress sweeps</h2>\n<p class=\"small\">Per controlled factor and level: the runs on the ")
                .append("sequences at that level; the median of the metric over successful runs with its ")
                .append("order-statistic interval; the failure rate with the interval clustered by sequence; the ")
                .append("breakdown level is the lowest level whose failure rate reaches the breakdown rate.</p>\n");
        for (FactorSweep s : sweeps) {
            h.append("<h3>").append(esc(s.factor())).append("</h3>\n<table><thead><tr><th class=\"l\">method</th>")
                    .append("<th>level</th><th>runs</th><th>failure rate</th><th>clustered interval</th>");
            List<FactorSweep.LevelMetric> first = s.methods().get(0).levels().get(0).metrics();
            for (FactorSweep.LevelMetric lm : first) {
                h.append("<th>").append(esc(lm.metric())).append(" median [interval]</th>");
            }
            h.append("<th>breakdown level</th></tr></thead><tbody>\n");
            for (FactorSweep.MethodSweep m : s.methods()) {
                for (FactorSweep.Level l : m.levels()) {
                    SuiteReport.Proportion p = l.failureRate();
                    h.append("<tr><td class=\"l\">").append(esc(m.method())).append("</td><td>").append(fmt(l.level()))
                            .append("</td><td>").append(l.runs()).append("</td><td>")
                            .append(p == null ? "&mdash;" : fmt(p.estimate())).append("</td><td>")
                            .append(p == null || p.clustered() == null ? "&mdash;" : bounds(new SuiteReport.Bounds(
                                    p.clustered().lower(), p.clustered().upper()))).append("</td>");
                    for (FactorSweep.LevelMetric lm : l.metrics()) {
                        h.append("<td>").append(fmt(lm.median())).append(" [").append(fmt(lm.lower())).append(", ")
                                .append(fmt(lm.upper())).append("]</td>");
                    }
                    h.append("<td>").append(m.breakdownLevel() == null ? "none" : fmt(m.breakdownLevel()))
                            .append("</td></tr>\n");
                }
            }
            h.append("</tbody></table>\n<div class=\"charts\">\n");
            svg.forEach((f, text) -> {
                if (f.name().startsWith("sweep_" + s.factor().toLowerCase(java.util.Locale.ROOT))) {
                    h.append(SuiteHtml.img(text, f.title()));
                }
            });
            h.append("</div>\n");
        }
    }

    private static void budgets(StringBuilder h, BudgetReport b) {
        if (b == null || b.resources() == null) {
            return;
        }
        h.append("<h2>Budget</h2>\n<p class=\"small\">Measured resources from <code>").append(esc(b.resources()))
                .append("</code> against the protocol's budget (real-time factor = the reference's duration / wall ")
                .append("time); a run over it is a ").append(b.policy().equals("fail") ? "failure of kind "
                        + "<code>budget</code>" : "warning").append(". ").append(b.unknownRuns())
                .append(" run(s) without a row: budget unknown.</p>\n<table><thead><tr><th class=\"l\">method</th>")
                .append("<th>runs</th><th>within</th><th>over</th><th>unknown</th><th>compliance</th></tr></thead>")
                .append("<tbody>\n");
        for (BudgetReport.MethodBudget m : b.methods()) {
            h.append("<tr><td class=\"l\">").append(esc(m.method())).append("</td><td>").append(m.runs())
                    .append("</td><td>").append(m.within()).append("</td><td>").append(m.over()).append("</td><td>")
                    .append(m.unknown()).append("</td><td>").append(fmt(m.compliance())).append("</td></tr>\n");
        }
        h.append("</tbody></table>\n");
        for (BudgetReport.RunBudget r : b.runs()) {
            if (r.status().equals("over")) {
                h.append("<div class=\"warn\">Over budget: ").append(esc(r.method())).append(" / ")
                        .append(esc(r.sequence())).append(" / seed ").append(r.seed()).append(": ")
                        .append(esc(String.join("; ", r.violations()))).append("</div>\n");
            }
        }
    }

    private static void slices(StringBuilder h, List<SliceReport> slices) {
        if (slices == null || slices.isEmpty()) {
            return;
        }
        h.append("<h2>Slices</h2>\n<p class=\"small\">The methods' table on the sequences of one domain, ")
                .append("environment, modality or ground-truth source.</p>\n<table><thead><tr><th class=\"l\">slice")
                .append("</th><th>sequences</th><th class=\"l\">method</th><th>runs</th><th>failures</th>")
                .append("<th>score S (mean)</th><th class=\"l\">mean of sequence means</th></tr></thead><tbody>\n");
        for (SliceReport s : slices) {
            for (SuiteReport.MethodSummary m : s.methods()) {
                StringBuilder metrics = new StringBuilder();
                for (SuiteReport.MetricSummary ms : m.metrics()) {
                    metrics.append(esc(ms.metric())).append(" ").append(fmt(ms.meanOfSequenceMeans())).append(" ");
                }
                h.append("<tr><td class=\"l\">").append(esc(s.dimension())).append(" = ").append(esc(s.value()))
                        .append("</td><td>").append(s.sequences().size()).append("</td><td class=\"l\">")
                        .append(esc(m.name())).append("</td><td>").append(m.runs()).append("</td><td>")
                        .append(m.failures()).append("</td><td>").append(fmt(m.score().mean())).append("</td><td class=\"l\">")
                        .append(metrics.toString().trim()).append("</td></tr>\n");
            }
        }
        h.append("</tbody></table>\n");
    }
}
