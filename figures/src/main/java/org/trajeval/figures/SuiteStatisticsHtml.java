package org.trajeval.figures;

import java.util.List;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.Ranking;
import org.trajeval.core.report.SuiteReport.VarianceSplit;

/**
 * The suite page's sections on many methods at once (Friedman, average ranks and the rank
 * diagram per metric) and on the split of each metric's variance between sequences and seeds.
 */
final class SuiteStatisticsHtml {
    private SuiteStatisticsHtml() {
    }

    /** Appends the rankings section (nothing with fewer than three methods). */
    static void rankings(StringBuilder h, SuiteReport r) {
        if (r.rankings() == null || r.rankings().isEmpty()) {
            return;
        }
        h.append("<h2>All methods at once: ranks</h2>\n<p class=\"small\">Per metric, each sequence ranks the ")
                .append("methods (1 = best, ties share their mean rank) over the sequences where every method has ")
                .append("a value. Friedman: &chi;<sup>2</sup><sub>F</sub> = (12/(nk(k+1)) &Sigma; S<sub>j</sub>")
                .append("<sup>2</sup> - 3n(k+1)) / C (tie-corrected), k-1 degrees of freedom; Iman-Davenport: ")
                .append("F<sub>F</sub> = (n-1)&chi;<sup>2</sup><sub>F</sub> / (n(k-1) - &chi;<sup>2</sup><sub>F</sub>)")
                .append(". In the diagram a bar joins methods no pair of which differs significantly by the ")
                .append("Holm-adjusted pairwise Wilcoxon tests.</p>\n");
        for (Ranking k : r.rankings()) {
            h.append("<h3>").append(SuiteHtml.esc(k.metric())).append("</h3>\n");
            if (k.friedman() == null) {
                h.append("<p>Not ranked: ").append(k.n()).append(" sequence").append(k.n() == 1 ? "" : "s")
                        .append(" where every method has a value (2 needed).</p>\n");
                continue;
            }
            h.append("<p>n = ").append(k.n()).append(" sequences, k = ").append(k.methods().size())
                    .append(" methods: Friedman &chi;<sup>2</sup> = ").append(SuiteHtml.fmt(k.friedman().statistic()))
                    .append(" (df ").append(k.friedman().df()).append("), p = ")
                    .append(SuiteHtml.fmt(k.friedman().pValue())).append("; Iman-Davenport F = ")
                    .append(k.imanDavenport().statistic() == null ? "&infin;"
                            : SuiteHtml.fmt(k.imanDavenport().statistic()))
                    .append(" (df ").append(k.imanDavenport().df()).append(", ")
                    .append(k.imanDavenport().dfDenominator()).append("), p = ")
                    .append(SuiteHtml.fmt(k.imanDavenport().pValue())).append(". Family: ")
                    .append(SuiteHtml.esc(k.family())).append(", &alpha; = ").append(SuiteHtml.fmt(k.alpha()))
                    .append(".</p>\n");
            if (RankDiagramSvg.drawable(k)) {
                h.append("<figure class=\"charts\">").append(RankDiagramSvg.render(k)).append("</figure>\n");
            }
        }
    }

    /** Appends the variance-split table. */
    static void variance(StringBuilder h, SuiteReport r) {
        h.append("<h2>Between sequences or between seeds?</h2>\n<p class=\"small\">One-way random-effects split ")
                .append("(ANOVA estimator) of each metric over the successful runs: &sigma;<sub>seq</sub> between ")
                .append("sequences, &sigma;<sub>seed</sub> between seeds of one sequence, in the metric's unit. ")
                .append("More seeds help when &sigma;<sub>seed</sub><sup>2</sup>/K exceeds &sigma;<sub>seq</sub>")
                .append("<sup>2</sup>; otherwise add sequences.</p>\n<table><thead><tr><th class=\"l\">method</th>")
                .append("<th class=\"l\">metric</th><th>sequences</th><th>K</th><th>&sigma;<sub>seq</sub></th>")
                .append("<th>&sigma;<sub>seed</sub></th><th>between-sequence share</th><th class=\"l\">advice</th>")
                .append("</tr></thead><tbody>\n");
        for (SuiteReport.MethodSummary m : r.methods()) {
            for (SuiteReport.MetricSummary ms : m.metrics()) {
                row(h, m.name(), ms.metric(), ms.variance());
            }
            row(h, m.name(), "score", m.scoreVariance());
        }
        h.append("</tbody></table>\n");
    }

    private static void row(StringBuilder h, String method, String metric, VarianceSplit v) {
        h.append("<tr><td class=\"l\">").append(SuiteHtml.esc(method)).append("</td><td class=\"l\">")
                .append(SuiteHtml.esc(metric)).append("</td>");
        if (v == null) {
            h.append("<td colspan=\"6\" class=\"l small\">not estimable (needs 2 sequences and a sequence with 2 ")
                    .append("values)</td></tr>\n");
            return;
        }
        for (String cell : List.of(Integer.toString(v.sequences()), SuiteHtml.fmt(v.seedsPerSequence()),
                SuiteHtml.fmt(v.sequenceSd()), SuiteHtml.fmt(v.seedSd()),
                v.sequenceShare() == null ? "&mdash;" : SuiteHtml.fmt(100.0 * v.sequenceShare()) + "&nbsp;%")) {
            h.append("<td>").append(cell).append("</td>");
        }
        h.append("<td class=\"l\">").append(v.advice().replace('_', ' ')).append("</td></tr>\n");
    }
}
