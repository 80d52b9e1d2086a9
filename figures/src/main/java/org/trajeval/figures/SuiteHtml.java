package org.trajeval.figures;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.report.SequencePlot;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.Bounds;
import org.trajeval.core.report.SuiteReport.Comparison;
import org.trajeval.core.report.SuiteReport.MethodSummary;
import org.trajeval.core.report.SuiteReport.MetricSummary;
import org.trajeval.core.report.SuiteReport.RunEntry;

/**
 * The human-readable page of a suite: one self-contained HTML file (inline CSS, charts as PNG
 * data URIs, no script and no network fetch) with the protocol, hygiene findings, the summary and
 * comparison tables with their intervals, box plots per method, and per sequence a trajectory
 * overlay and an error-over-time plot.
 */
public final class SuiteHtml {
    /** File name of the page. */
    public static final String FILE = "report.html";

    private SuiteHtml() {
    }

    /** Writes {@link #FILE} into {@code dir} (atomically). */
    public static void write(SuiteReport report, List<SequencePlot> plots, Path dir) {
        ReportJson.writeAtomically(dir.resolve(FILE), render(report, plots));
    }

    /** @return the page */
    public static String render(SuiteReport r, List<SequencePlot> plots) {
        StringBuilder h = new StringBuilder(1 << 16);
        SuiteReport.Protocol p = r.protocol();
        h.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n<title>trajeval suite: ")
                .append(esc(p.dataset())).append("</title>\n<style>\n")
                .append("body{font-family:system-ui,-apple-system,Segoe UI,Roboto,sans-serif;margin:2em auto;")
                .append("max-width:1200px;color:#222;padding:0 1em}\n")
                .append("table{border-collapse:collapse;margin:0.5em 0 1.5em}th,td{border:1px solid #ccc;")
                .append("padding:4px 8px;text-align:right;font-variant-numeric:tabular-nums}")
                .append("th{background:#f3f3f3}td.l,th.l{text-align:left}\n")
                .append(".warn{background:#fff3cd;border:1px solid #e0b000;padding:0.6em 1em;margin:0.5em 0}\n")
                .append(".bad{background:#fde2e1;border:1px solid #d33;padding:0.6em 1em;margin:0.5em 0}\n")
                .append(".charts img{margin:4px;border:1px solid #ddd}.small{color:#666;font-size:0.9em}\n")
                .append("code{background:#f6f6f6;padding:0 3px}\n</style></head><body>\n");
        h.append("<h1>Benchmark suite: ").append(esc(p.dataset())).append("</h1>\n");
        h.append("<p class=\"small\">trajeval ").append(esc(r.version())).append(", report schema ")
                .append(esc(r.schema())).append(" v").append(r.schemaVersion()).append(", manifest <code>")
                .append(esc(p.manifest())).append("</code></p>\n");

        protocol(h, r);
        hygiene(h, r);
        summary(h, r);
        comparisons(h, r);
        boxes(h, r);
        sequences(h, plots);
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
                + p.analysis().bootstrapResamples() + " (seed " + p.analysis().seed() + "), Wilcoxon exact up to n = "
                + p.analysis().wilcoxonExactMaxN());
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
                .append(pct(level)).append("</th><th>score S (mean &plusmn; sd)</th>");
        for (String k : keys) {
            h.append("<th>").append(esc(k)).append("<br><span class=\"small\">mean of sequence means</span></th>");
        }
        h.append("</tr></thead><tbody>\n");
        for (MethodSummary m : r.methods()) {
            h.append("<tr><td class=\"l\"><b>").append(esc(m.name())).append("</b></td><td>").append(m.runs())
                    .append("</td><td>").append(m.failures()).append("</td>");
            if (m.failureRate() == null) {
                h.append("<td></td><td></td><td></td>");
            } else {
                h.append("<td>").append(fmt(m.failureRate().estimate())).append("</td><td>")
                        .append(bounds(m.failureRate().wilson())).append("</td><td>")
                        .append(bounds(m.failureRate().clopperPearson())).append("</td>");
            }
            h.append("<td>").append(fmt(m.score().mean())).append(" &plusmn; ").append(fmt(m.score().sd()))
                    .append("</td>");
            for (String k : keys) {
                MetricSummary ms = m.metrics().stream().filter(x -> x.metric().equals(k)).findFirst().orElse(null);
                h.append("<td>").append(ms == null ? "" : fmt(ms.meanOfSequenceMeans())).append("</td>");
            }
            h.append("</tr>\n");
        }
        h.append("</tbody></table>\n");
    }

    private static void comparisons(StringBuilder h, SuiteReport r) {
        double level = r.protocol().analysis().confidenceLevel();
        h.append("<h2>Paired comparisons</h2>\n<p class=\"small\">d<sub>s</sub> = A<sub>s</sub> - B<sub>s</sub> per ")
                .append("sequence (mean over the common seeds); for error metrics lower is better (d &lt; 0 favours")
                .append(" A), for the score higher is better. t-interval: d&#772; &plusmn; t<sub>n-1,1-&alpha;/2</sub>")
                .append(" s<sub>d</sub>/&radic;n; bootstrap: percentile, resampling whole sequences.</p>\n")
                .append("<table><thead><tr><th class=\"l\">A</th><th class=\"l\">B</th><th class=\"l\">metric</th>")
                .append("<th>n</th><th>mean d</th><th>t-interval ").append(pct(level)).append("</th><th>bootstrap ")
                .append(pct(level)).append("</th><th>Wilcoxon p</th><th class=\"l\">which test applies</th>")
                .append("</tr></thead><tbody>\n");
        for (Comparison c : r.comparisons()) {
            h.append("<tr><td class=\"l\">").append(esc(c.methodA())).append("</td><td class=\"l\">")
                    .append(esc(c.methodB())).append("</td><td class=\"l\">").append(esc(c.metric()))
                    .append("</td><td>").append(c.n()).append("</td><td>").append(fmt(c.meanDifference()))
                    .append("</td><td>").append(bounds(c.tInterval())).append("</td><td>")
                    .append(bounds(c.bootstrap())).append("</td><td>")
                    .append(c.wilcoxon() == null ? "" : fmt(c.wilcoxon().pValue()) + " <span class=\"small\">("
                            + esc(c.wilcoxon().method().replace('_', ' ')) + ")</span>")
                    .append("</td><td class=\"l small\">").append(esc(c.primary())).append("</td></tr>\n");
        }
        h.append("</tbody></table>\n");
    }

    private static void boxes(StringBuilder h, SuiteReport r) {
        List<String> methods = r.methods().stream().map(MethodSummary::name).toList();
        h.append("<h2>Distribution over runs</h2>\n<div class=\"charts\">\n");
        List<String> keys = new ArrayList<>(r.protocol().score().stream().map(SuiteReport.ScoreTerm::metric).toList());
        if (!keys.contains("ate_trans_rmse_m")) {
            keys.add(0, "ate_trans_rmse_m");
        }
        for (String k : keys) {
            List<double[]> values = new ArrayList<>();
            for (String m : methods) {
                values.add(r.runs().stream().filter(x -> x.method().equals(m) && x.ok() && x.metrics() != null
                        && x.metrics().get(k) != null).mapToDouble(x -> x.metrics().get(k)).toArray());
            }
            if (values.stream().allMatch(v -> v.length == 0)) {
                continue;
            }
            h.append(img(SuiteCharts.boxes(k + " per method (successful runs)", k, methods, values), k));
        }
        h.append("</div>\n");
    }

    private static void sequences(StringBuilder h, List<SequencePlot> plots) {
        h.append("<h2>Sequences</h2>\n<p class=\"small\">Each method's run with the first common seed, moved by ")
                .append("the alignment its evaluation fitted; error against the reference interpolated at the ")
                .append("estimate's stamps.</p>\n");
        for (SequencePlot p : plots) {
            h.append("<h3>").append(esc(p.sequence())).append("</h3>\n<div class=\"charts\">")
                    .append(img(SuiteCharts.overlay(p), "trajectories " + p.sequence()))
                    .append(img(SuiteCharts.errorOverTime(p), "error over time " + p.sequence()))
                    .append("</div>\n");
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

    private static String img(String dataUri, String alt) {
        return "<img src=\"" + dataUri + "\" alt=\"" + esc(alt) + "\">";
    }

    private static void kv(StringBuilder h, String k, String v) {
        h.append("<tr><th class=\"l\">").append(esc(k)).append("</th><td class=\"l\">").append(esc(v))
                .append("</td></tr>\n");
    }

    private static String bounds(Bounds b) {
        return b == null ? "&mdash;" : "[" + fmt(b.lower()) + ", " + fmt(b.upper()) + "]";
    }

    private static String pct(double level) {
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
