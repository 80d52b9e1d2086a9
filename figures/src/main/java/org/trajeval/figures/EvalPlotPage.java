package org.trajeval.figures;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Base64;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.report.SavedEvaluation;

/**
 * Writes the plots of one evaluation into a folder: every figure as {@code NAME.svg} and
 * {@code NAME.png}, and {@code index.html}, one self-contained page (figures as SVG data URIs,
 * inline CSS, no script, no network) with the numbers table and the figures.
 */
public final class EvalPlotPage {
    /** File name of the page. */
    public static final String INDEX = "index.html";

    private EvalPlotPage() {
    }

    /**
     * Draws and writes everything.
     *
     * @param progress told after each figure (figures done, figures in all)
     * @return the figures written, in page order
     */
    public static List<Figure> write(SavedEvaluation saved, PlotPlane plane, Path dir, Progress progress) {
        List<Figure> figures = EvalFigures.of(saved, plane);
        StringBuilder body = new StringBuilder();
        int done = 0;
        for (Figure f : figures) {
            String svg = FigureFiles.svg(f);
            ReportJson.writeAtomically(dir.resolve(f.name() + ".svg"), svg);
            ReportJson.writeAtomically(dir.resolve(f.name() + ".png"), FigureFiles.png(f, 1.0));
            body.append("<figure><img src=\"data:image/svg+xml;base64,")
                    .append(Base64.getEncoder().encodeToString(svg.getBytes(StandardCharsets.UTF_8)))
                    .append("\" alt=\"").append(SvgCanvas.escape(f.title())).append("\" width=\"")
                    .append(FigurePainter.WIDTH).append("\" height=\"").append(FigurePainter.HEIGHT)
                    .append("\"><figcaption><a href=\"").append(f.name()).append(".svg\">SVG</a> &middot; <a href=\"")
                    .append(f.name()).append(".png\">PNG</a></figcaption></figure>\n");
            progress.done(++done, figures.size());
        }
        ReportJson.writeAtomically(dir.resolve(INDEX), page(saved.report(), body.toString()));
        return figures;
    }

    /** Progress of the drawing. */
    @FunctionalInterface
    public interface Progress {
        void done(int figures, int total);

        /** @return a listener that ignores progress */
        static Progress none() {
            return (a, b) -> { };
        }
    }

    static String page(EvaluationReport r, String figures) {
        StringBuilder h = new StringBuilder(figures.length() + 8192);
        String ref = SvgCanvas.escape(r.inputs().reference().path());
        String est = SvgCanvas.escape(r.inputs().estimate().path());
        h.append("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n")
                .append("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n")
                .append("<title>trajeval: ").append(est).append(" against ").append(ref).append("</title>\n<style>\n")
                .append("body{font-family:system-ui,sans-serif;margin:1.5em auto;max-width:1560px;color:#222;")
                .append("padding:0 1em}\n.scroll{overflow-x:auto}table{border-collapse:collapse;margin:0.5em 0 1em}")
                .append("th,td{border:1px solid #ccc;padding:3px 8px;text-align:right;")
                .append("font-variant-numeric:tabular-nums}th{background:#f3f3f3}td.l,th.l{text-align:left}\n")
                .append(".figs{display:flex;flex-wrap:wrap;gap:8px}figure{margin:0}")
                .append("figure img{max-width:100%;height:auto;border:1px solid #ddd}")
                .append("figcaption{font-size:0.85em;color:#666}\n</style></head><body>\n")
                .append("<h1>Evaluation: <code>").append(est).append("</code></h1>\n<p>reference <code>").append(ref)
                .append("</code> (").append(r.inputs().reference().poses()).append(" poses), estimate <code>")
                .append(est).append("</code> (").append(r.inputs().estimate().poses()).append(" poses); convention ")
                .append(SvgCanvas.escape(r.convention())).append(", association ")
                .append(SvgCanvas.escape(r.association().method())).append(" (").append(r.association().matched())
                .append(" matched, ").append(r.association().dropped()).append(" estimate poses dropped), ")
                .append(SvgCanvas.escape(EvalFigures.alignment(r))).append("; RPE ")
                .append(SvgCanvas.escape(EvalFigures.rpeHorizon(r.rpe()))).append(", ").append(r.rpe().pairs())
                .append(" pairs.</p>\n<div class=\"scroll\"><table><thead><tr><th class=\"l\">error</th>")
                .append("<th>RMSE</th><th>mean</th><th>median</th><th>std</th><th>min</th><th>max</th><th>n</th>")
                .append("</tr></thead><tbody>\n");
        row(h, "ATE translation (m)", r.ate().transM(), 1);
        row(h, "ATE rotation (deg)", r.ate().rotRad(), 180 / Math.PI);
        row(h, "RPE translation (m)", r.rpe().transM(), 1);
        row(h, "RPE rotation (deg)", r.rpe().rotRad(), 180 / Math.PI);
        h.append("</tbody></table></div>\n");
        if (r.drift() != null) {
            h.append("<p>KITTI drift over ").append(r.drift().segments()).append(" segments: translation ")
                    .append(num(r.drift().transPct(), 1)).append(" %, rotation ")
                    .append(num(r.drift().rotDegPerM(), 100)).append(" deg/100 m.</p>\n");
        }
        h.append("<div class=\"figs\">\n").append(figures).append("</div>\n</body></html>\n");
        return h.toString();
    }

    private static void row(StringBuilder h, String name, EvaluationReport.Stats s, double f) {
        h.append("<tr><td class=\"l\">").append(name).append("</td><td>").append(num(s.rmse(), f)).append("</td><td>")
                .append(num(s.mean(), f)).append("</td><td>").append(num(s.median(), f)).append("</td><td>")
                .append(num(s.std(), f)).append("</td><td>").append(num(s.min(), f)).append("</td><td>")
                .append(num(s.max(), f)).append("</td><td>").append(s.n()).append("</td></tr>\n");
    }

    private static String num(Double v, double f) {
        return v == null ? "&mdash;" : String.format(Locale.ROOT, "%.6g", v * f);
    }
}
