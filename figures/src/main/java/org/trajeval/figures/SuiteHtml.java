package org.trajeval.figures;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Base64;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.report.SequencePlot;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.Bounds;
import org.trajeval.core.report.SuiteReport.Comparison;
import org.trajeval.core.report.SuiteReport.MethodSummary;
import org.trajeval.core.report.SuiteReport.MetricSummary;
import org.trajeval.core.report.SuiteReport.RunEntry;
import org.trajeval.core.stats.Interval;
import org.trajeval.core.stats.PairedTInterval;

/**
 * The human-readable page of a suite: one self-contained HTML file (inline CSS, figures as SVG
 * data URIs, no script and no network fetch) with the protocol, hygiene findings, the summary,
 * comparison and per-sequence tables with their intervals, box plots per method of every error
 * ({@link SuiteFigures}), and per sequence a trajectory overlay and an error-over-time plot.
 */
public final class SuiteHtml {
    /** File name of the page. */
    public static final String FILE = "report.html";

    private SuiteHtml() {
    }

    /** Folder (inside the report folder) of the figures as SVG files, for papers. */
    public static final String FIGURES = "figures";

    /**
     * Writes {@link #FILE} into {@code dir}, and every figure as {@code figures/NN_NAME.svg} and
     * {@code figures/NN_NAME.pdf} (vector, for a paper; each atomically).
     */
    public static void write(SuiteReport report, List<SequencePlot> plots, Path dir) {
        List<Figure> figures = figures(report, plots);
        Map<Figure, String> svg = new LinkedHashMap<>();
        int i = 0;
        for (Figure f : figures) {
            String text = FigureFiles.svg(f);
            svg.put(f, text);
            String stem = String.format(Locale.ROOT, "%02d_%s", ++i, f.name());
            ReportJson.writeAtomically(dir.resolve(FIGURES).resolve(stem + ".svg"), text);
            ReportJson.writeAtomically(dir.resolve(FIGURES).resolve(stem + ".pdf"), FigureFiles.pdf(f));
        }
        ReportJson.writeAtomically(dir.resolve(FILE), render(report, plots, svg));
    }

    /** @return the page, figures drawn here */
    public static String render(SuiteReport r, List<SequencePlot> plots) {
        Map<Figure, String> svg = new LinkedHashMap<>();
        for (Figure f : figures(r, plots)) {
            svg.put(f, FigureFiles.svg(f));
        }
        return render(r, plots, svg);
    }

    /** @return every figure of the page: the box plots, then per sequence the trajectories and the error */
    static List<Figure> figures(SuiteReport r, List<SequencePlot> plots) {
        List<Figure> out = new ArrayList<>(SuiteFigures.boxes(r));
        out.addAll(SweepFigures.of(r));
        for (SequencePlot p : plots) {
            out.add(SuiteFigures.overlay(p, PlotPlane.AUTO));
            out.add(SuiteFigures.errorOverTime(p));
        }
        return out;
    }

    private static String render(SuiteReport r, List<SequencePlot> plots, Map<Figure, String> svg) {
        StringBuilder h = new StringBuilder(1 << 16);
        SuiteReport.Protocol p = r.protocol();
        h.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>trajeval suite: ")
                .append(esc(p.dataset())).append("</title>\n<style>\n")
                .append("body{font-family:system-ui,-apple-system,Segoe UI,Roboto,sans-serif;margin:2em auto;")
                .append("max-width:1600px;color:#222;padding:0 1em}\n.scroll{overflow-x:auto}\n")
                .append("table{border-collapse:collapse;margin:0.5em 0 1.5em}th,td{border:1px solid #ccc;")
                .append("padding:4px 8px;text-align:right;font-variant-numeric:tabular-nums}")
                .append("th{background:#f3f3f3}td.l,th.l{text-align:left}\n")
                .append(".warn{background:#fff3cd;border:1px solid #e0b000;padding:0.6em 1em;margin:0.5em 0}\n")
                .append(".bad{background:#fde2e1;border:1px solid #d33;padding:0.6em 1em;margin:0.5em 0}\n")
                .append(".charts{display:flex;flex-wrap:wrap;gap:6px}.charts img{max-width:100%;height:auto;")
                .append("border:1px solid #ddd}.small{color:#666;font-size:0.9em}\n")
                .append("code{background:#f6f6f6;padding:0 3px}\n")
                .append(".wide{overflow-x:auto}.wide td{white-space:nowrap}\n</style></head><body>\n");
        h.append("<h1>Benchmark suite: ").append(esc(p.dataset())).append("</h1>\n");
        h.append("<p class=\"small\">trajeval ").append(esc(r.version())).append(", report schema ")
                .append(esc(r.schema())).append(" v").append(r.schemaVersion()).append(", manifest <code>")
                .append(esc(p.manifest())).append("</code></p>\n");

        protocol(h, r);
        hygiene(h, r);
        summary(h, r);
        comparisons(h, r);
        SuiteStatisticsHtml.rankings(h, r);
        SuiteStatisticsHtml.variance(h, r);
        SimRealHtml.sections(h, r, svg);
        perSequence(h, r);
        boxes(h, r, svg);
        sequences(h, plots, svg);
        failures(h, r);
        h.append("</body></html>\n");
        return h.toString();
    }

    private static void protocol(StringBuilder h, SuiteReport r) {
        SuiteReport.Protocol p = r.protocol();
        SuiteReport.MetricSettings m = p.metrics();
        h.append("<h2>Protocol</h2>\n<table><tbody>\n");
        kv(h, "dataset", p.dataset());
        kv(h, "evaluated splits", String.join(", ", p.evaluatedSplits()));
        kv(h, "sequences", p.sequences().stream().filter(s -> p.evaluatedSplits().contains(s.split())).count()
                + " evaluated of " + p.sequences().size());
        kv(h, "metrics", "convention " + m.convention() + ", association " + m.association() + ", overlap "
                + m.overlap() + ", alignment " + m.alignment() + ", RPE delta " + fmt(m.rpeDelta()) + " "
                + m.rpeUnit() + " (" + m.rpePairs() + ")");
        kv(h, "seeds", "declared " + p.seeds().declared() + ", common (used) " + p.seeds().common());
        StringBuilder score = new StringBuilder("S = 100 &sum; w<sub>j</sub> max(0, 1 - m<sub>j</sub>/c<sub>j</sub>): ");
        for (SuiteReport.ScoreTerm t : p.score()) {
            score.append(esc(t.metric())).append(" (c = ").append(fmt(t.cap())).append(", w = ")
                    .append(fmt(t.weight())).append(") ");
        }
        h.append("<tr><th class=\"l\">score</th><td class=\"l\">").append(score).append("</td></tr>\n");
        SuiteReport.FailureSettings f = p.failure();
        kv(h, "failure", String.join(", ", f.always()) + (f.minCoverage() == null ? "" : ", coverage < "
                + fmt(f.minCoverage())) + (f.maxAteTransRmseM() == null ? "" : ", ATE RMSE > "
                + fmt(f.maxAteTransRmseM()) + " m") + (f.divergenceTransM() == null ? "" : ", any error > "
                + fmt(f.divergenceTransM()) + " m (diverged)"));
        SuiteReport.BudgetEntry b = p.budget();
        kv(h, "budget", b.device() + (b.cores() == null ? "" : ", " + b.cores() + " cores") + ", real-time factor "
                + fmt(b.realTimeFactor()) + ", memory cap " + b.memoryCapMib() + " MiB");
        kv(h, "statistics", "confidence " + fmt(p.analysis().confidenceLevel()) + ", bootstrap B = "
                + p.analysis().bootstrapResamples() + " (seed " + p.analysis().seed() + "), Wilcoxon exact up to "
                + p.analysis().wilcoxonExactMaxN() + " non-zero differences; pairwise p-values Holm-adjusted per metric; "
                + "failure-rate intervals clustered by sequence (Korn-Graubard); planning at power "
                + fmt(powerOf(r)));
        h.append("</tbody></table>\n");
    }

    private static void hygiene(StringBuilder h, SuiteReport r) {
        h.append("<h2>Hygiene</h2>\n");
        if (r.hygiene().warnings().isEmpty()) {
            h.append("<p>Splits are session-consistent and every method has the same seed set.</p>\n");
        }
        for (String w : r.hygiene().warnings()) {
            h.append("<div class=\"").append(w.startsWith("LEAKAGE") ? "bad" : "warn").append("\">")
                    .append(esc(w)).append("</div>\n");
        }
    }

    private static void summary(StringBuilder h, SuiteReport r) {
        List<String> keys = r.protocol().score().stream().map(SuiteReport.ScoreTerm::metric).toList();
        double level = r.protocol().analysis().confidenceLevel();
        h.append("<h2>Methods</h2>\n<table><thead><tr><th class=\"l\">method</th><th>runs</th><th>failures</th>")
                .append("<th>failure rate</th><th>Wilson ").append(pct(level)).append("</th><th>Clopper-Pearson ")
                .append(pct(level)).append("</th><th>clustered by sequence ").append(pct(level))
                .append("<br><span class=\"small\">Korn-Graubard</span></th><th>score S (mean &plusmn; sd)</th>");
        for (String k : keys) {
            h.append("<th>").append(esc(MetricLabel.of(k).label())).append("<br><span class=\"small\">mean of sequence ")
                    .append("means (").append(esc(k)).append(")</span></th>");
        }
        h.append("</tr></thead><tbody>\n");
        for (MethodSummary m : r.methods()) {
            h.append("<tr><td class=\"l\"><b>").append(esc(m.name())).append("</b></td><td>").append(m.runs())
                    .append("</td><td>").append(m.failures()).append("</td>");
            if (m.failureRate() == null) {
                h.append("<td></td><td></td><td></td><td></td>");
            } else {
                SuiteReport.ClusteredBounds cl = m.failureRate().clustered();
                h.append("<td>").append(fmt(m.failureRate().estimate())).append("</td><td>")
                        .append(bounds(m.failureRate().wilson())).append("</td><td>")
                        .append(bounds(m.failureRate().clopperPearson())).append("</td><td>")
                        .append(cl == null ? "&mdash;" : bounds(new Bounds(cl.lower(), cl.upper()))
                                + " <span class=\"small\">(design effect " + fmt(cl.designEffect()) + ")</span>")
                        .append("</td>");
            }
            h.append("<td>").append(fmt(m.score().mean())).append(" &plusmn; ").append(fmt(m.score().sd()))
                    .append("</td>");
            for (String k : keys) {
                MetricSummary ms = m.metrics().stream().filter(x -> x.metric().equals(k)).findFirst().orElse(null);
                h.append("<td>").append(ms == null || ms.meanOfSequenceMeans() == null ? "" : fmt(ms.meanOfSequenceMeans()
                        * MetricLabel.of(k).factor())).append("</td>");
            }
            h.append("</tr>\n");
        }
        h.append("</tbody></table>\n");
    }

    private static void comparisons(StringBuilder h, SuiteReport r) {
        double level = r.protocol().analysis().confidenceLevel();
        h.append("<h2>Paired comparisons</h2>\n<p class=\"small\">d<sub>s</sub> = A<sub>s</sub> - B<sub>s</sub> per ")
                .append("sequence (each method's mean over its own successful seeds among the common ones); for error")
                .append(" metrics lower is better (d &lt; 0 favours A), for the score higher is better. n: paired ")
                .append("sequences; non-zero: differences the Wilcoxon test ranks. t-interval: d&#772; &plusmn; ")
                .append("t<sub>n-1,1-&alpha;/2</sub> s<sub>d</sub>/&radic;n; bootstrap: percentile, resampling whole ")
                .append("sequences; Hodges-Lehmann: median of the Walsh averages with its exact or asymptotic ")
                .append("interval; Holm: p adjusted over the metric's pairwise tests; detectable: the smallest mean ")
                .append("difference this n detects with ").append(pct(powerOf(r))).append(" power.</p>\n")
                .append("<div class=\"wide\"><table><thead><tr><th class=\"l\">A</th><th class=\"l\">B</th>")
                .append("<th class=\"l\">metric</th><th>n</th><th>non-zero</th><th>mean d</th><th>t-interval ").append(pct(level))
                .append("</th><th>bootstrap ").append(pct(level)).append("</th><th>Hodges-Lehmann ").append(pct(level))
                .append("</th><th>A better</th><th>Wilcoxon p</th><th>Holm p</th><th>detectable</th>")
                .append("<th class=\"l\">test (hover: why)</th></tr></thead><tbody>\n");
        for (Comparison c : r.comparisons()) {
            SuiteReport.HodgesLehmannEntry hl = c.hodgesLehmann();
            h.append("<tr><td class=\"l\">").append(esc(c.methodA())).append("</td><td class=\"l\">")
                    .append(esc(c.methodB())).append("</td><td class=\"l\">").append(esc(MetricLabel.of(c.metric()).label()))
                    .append("</td><td>").append(c.n()).append("</td><td>").append(c.nonzeroDifferences())
                    .append("</td><td>").append(fmt(c.meanDifference()))
                    .append("</td><td>").append(bounds(c.tInterval())).append("</td><td>")
                    .append(bounds(c.bootstrap())).append("</td><td>")
                    .append(hl == null ? "&mdash;" : fmt(hl.estimate()) + " " + bounds(new Bounds(hl.lower(), hl.upper()))
                            + " <span class=\"small\">(" + esc(hl.method()) + ")</span>")
                    .append("</td><td>")
                    .append(c.wins() == null ? "&mdash;" : c.wins().aBetter() + "/" + c.n() + " ("
                            + fmt(100.0 * c.wins().shareABetter()) + "&nbsp;%)")
                    .append("</td><td>")
                    .append(c.wilcoxon() == null ? "&mdash;" : fmt(c.wilcoxon().pValue()) + " <span class=\"small\">("
                            + esc(c.wilcoxon().method().replace('_', ' ')) + ")</span>")
                    .append("</td><td>").append(c.holm() == null ? "&mdash;" : fmt(c.holm().pAdjusted()))
                    .append("</td><td>").append(c.planning() == null ? "&mdash;"
                            : fmt(c.planning().minDetectableDifference()))
                    .append("</td><td class=\"l\" title=\"").append(esc(c.primary())).append("\">")
                    .append(esc(c.testLabel())).append("</td></tr>\n");
        }
        h.append("</tbody></table></div>\n<ul class=\"small\">\n");
        java.util.Map<String, List<String>> why = new java.util.LinkedHashMap<>();
        for (Comparison c : r.comparisons()) {
            why.computeIfAbsent(c.primary(), k -> new ArrayList<>()).add(c.methodA() + "-" + c.methodB() + " "
                    + c.metric());
        }
        why.forEach((reason, rows) -> h.append("<li>").append(esc(reason)).append(": ")
                .append(esc(String.join(", ", rows))).append("</li>\n"));
        h.append("</ul>\n");
    }

    private static double powerOf(SuiteReport r) {
        Double p = r.protocol().analysis().power();
        return p == null ? org.trajeval.core.stats.PowerPlanning.DEFAULT_POWER : p;
    }

    private static void perSequence(StringBuilder h, SuiteReport r) {
        double level = r.protocol().analysis().confidenceLevel();
        List<String> keys = r.protocol().score().stream().map(SuiteReport.ScoreTerm::metric).toList();
        List<String> methods = r.methods().stream().map(MethodSummary::name).toList();
        List<String> sequences = r.runs().stream().map(RunEntry::sequence).distinct().toList();
        h.append("<h2>Per sequence</h2>\n<p class=\"small\">Mean over the successful seeds &plusmn; half-width of ")
                .append("the t-interval ").append(pct(level)).append(" (x&#772; &plusmn; t<sub>n-1</sub> s/&radic;n)")
                .append(", and the number of successful seeds n; &mdash; where no seed succeeded.</p>\n");
        for (String k : keys) {
            MetricLabel label = MetricLabel.of(k);
            h.append("<div class=\"scroll\"><table><caption>").append(esc(label.label()))
                    .append("</caption><thead><tr><th class=\"l\">sequence</th>");
            for (String m : methods) {
                h.append("<th>").append(esc(m)).append("</th>");
            }
            h.append("</tr></thead><tbody>\n");
            for (String seq : sequences) {
                h.append("<tr><td class=\"l\">").append(esc(seq)).append("</td>");
                for (String m : methods) {
                    double[] v = r.runs().stream().filter(x -> x.method().equals(m) && x.sequence().equals(seq)
                            && x.ok() && x.metrics() != null && x.metrics().get(k) != null)
                            .mapToDouble(x -> x.metrics().get(k) * label.factor()).toArray();
                    h.append("<td>").append(meanInterval(v, level)).append("</td>");
                }
                h.append("</tr>\n");
            }
            h.append("</tbody></table></div>\n");
        }
    }

    private static String meanInterval(double[] v, double level) {
        if (v.length == 0) {
            return "&mdash;";
        }
        if (v.length == 1) {
            return fmt(v[0]) + " <span class=\"small\">(n = 1)</span>";
        }
        Interval ci = PairedTInterval.of(v, level);
        return fmt(ci.estimate()) + " &plusmn; " + fmt(ci.upper() - ci.estimate()) + " <span class=\"small\">(n = "
                + v.length + ")</span>";
    }

    private static void boxes(StringBuilder h, SuiteReport r, Map<Figure, String> svg) {
        h.append("<h2>Distribution over runs</h2>\n<p class=\"small\">One box per method over its successful runs ")
                .append("(every sequence and seed): box from the first to the third quartile, line at the median, ")
                .append("whiskers to the last run within 1.5 IQR. Axes start at zero.</p>\n<div class=\"charts\">\n");
        svg.forEach((f, text) -> {
            if (f.name().startsWith("box_")) {
                h.append(img(text, f.title()));
            }
        });
        h.append("</div>\n");
    }

    private static void sequences(StringBuilder h, List<SequencePlot> plots, Map<Figure, String> svg) {
        h.append("<h2>Sequences</h2>\n<p class=\"small\">Every seed of every method, moved by the alignment its ")
                .append("evaluation fitted (the title says which); the bold line is the seed with the median RMS ")
                .append("error. Position error against the reference interpolated at the estimate's stamps, over ")
                .append("time from the reference's first stamp: per method the median over seeds and the shaded ")
                .append("min-max envelope.</p>\n");
        // figures() puts the box plots first, then per sequence its overlay and its error plot
        List<Figure> figs = svg.keySet().stream().filter(f -> !f.name().startsWith("box_")).toList();
        for (int i = 0; i < plots.size(); i++) {
            h.append("<h3>").append(esc(plots.get(i).sequence())).append("</h3>\n<div class=\"charts\">");
            for (Figure f : figs.subList(2 * i, 2 * i + 2)) {
                h.append(img(svg.get(f), f.title()));
            }
            h.append("</div>\n");
        }
    }

    private static void failures(StringBuilder h, SuiteReport r) {
        List<RunEntry> failed = r.runs().stream().filter(x -> !x.ok()).toList();
        h.append("<h2>Failed runs (").append(failed.size()).append(")</h2>\n");
        if (failed.isEmpty()) {
            h.append("<p>None.</p>\n");
            return;
        }
        h.append("<table><thead><tr><th class=\"l\">method</th><th class=\"l\">sequence</th><th>seed</th>")
                .append("<th class=\"l\">reason</th><th class=\"l\">detail</th></tr></thead><tbody>\n");
        for (RunEntry x : failed) {
            h.append("<tr><td class=\"l\">").append(esc(x.method())).append("</td><td class=\"l\">")
                    .append(esc(x.sequence())).append("</td><td>").append(x.seed()).append("</td><td class=\"l\">")
                    .append(esc(x.failure().reason())).append("</td><td class=\"l\">")
                    .append(esc(x.failure().detail())).append("</td></tr>\n");
        }
        h.append("</tbody></table>\n");
    }

    static String img(String svg, String alt) {
        return "<img src=\"data:image/svg+xml;base64," + Base64.getEncoder().encodeToString(svg.getBytes(
                StandardCharsets.UTF_8)) + "\" alt=\"" + esc(alt) + "\" width=\"" + FigurePainter.WIDTH
                + "\" height=\"" + FigurePainter.HEIGHT + "\">";
    }

    private static void kv(StringBuilder h, String k, String v) {
        h.append("<tr><th class=\"l\">").append(esc(k)).append("</th><td class=\"l\">").append(esc(v))
                .append("</td></tr>\n");
    }

    static String bounds(Bounds b) {
        return b == null ? "&mdash;" : "[" + fmt(b.lower()) + ", " + fmt(b.upper()) + "]";
    }

    static String pct(double level) {
        return fmt(100.0 * level) + "&nbsp;%";
    }

    static String fmt(Double v) {
        if (v == null || !Double.isFinite(v)) {
            return "&mdash;";
        }
        double a = Math.abs(v);
        if (v == Math.rint(v) && a < 1e6) {
            return Long.toString((long) (double) v);
        }
        if (a != 0 && (a < 1e-3 || a >= 1e5)) {
            return String.format(Locale.ROOT, "%.3g", v);
        }
        return String.format(Locale.ROOT, "%.4f", v);
    }

    static String esc(String s) {
        if (s == null) {
            return "";
        }
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
