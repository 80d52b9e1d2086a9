package org.trajeval.figures;

import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.SavedEvaluation;

/**
 * The plots of one evaluation as a {@link FigurePage}: every figure as SVG and PNG, and
 * {@code index.html} with the numbers table above the figures: inputs, association, alignment,
 * coverage and the longest stretch without an estimate pose, the report's warnings, the error
 * statistics and KITTI drift.
 */
public final class EvalPlotPage {
    /** File name of the page. */
    public static final String INDEX = FigurePage.INDEX;

    private EvalPlotPage() {
    }

    /**
     * Draws and writes everything.
     *
     * @param progress told after each figure (figures done, figures in all)
     * @return the figures written, in page order
     */
    public static List<Figure> write(SavedEvaluation saved, PlotPlane plane, Path dir, FigurePage.Progress progress) {
        return write(saved, plane, dir, FigureFormat.DEFAULT, progress);
    }

    /** As above, every figure in the given formats. */
    public static List<Figure> write(SavedEvaluation saved, PlotPlane plane, Path dir,
            java.util.Set<FigureFormat> formats, FigurePage.Progress progress) {
        List<Figure> figures = EvalFigures.of(saved, plane);
        EvaluationReport r = saved.report();
        FigurePage.write("Evaluation: " + r.inputs().estimate().path(), numbers(r), figures, dir, formats, progress);
        return figures;
    }

    static String numbers(EvaluationReport r) {
        StringBuilder h = new StringBuilder(4096);
        String ref = SvgCanvas.escape(r.inputs().reference().path());
        String est = SvgCanvas.escape(r.inputs().estimate().path());
        h.append("<p>reference <code>").append(ref)
                .append("</code> (").append(r.inputs().reference().poses()).append(" poses), estimate <code>")
                .append(est).append("</code> (").append(r.inputs().estimate().poses()).append(" poses); convention ")
                .append(SvgCanvas.escape(r.convention())).append(", association ")
                .append(SvgCanvas.escape(r.association().method())).append(" (").append(r.association().matched())
                .append(" matched, ").append(r.association().dropped()).append(" estimate poses dropped), ")
                .append(SvgCanvas.escape(EvalFigures.alignment(r))).append("; RPE ")
                .append(SvgCanvas.escape(EvalFigures.rpeHorizon(r.rpe()))).append(", ").append(r.rpe().pairs())
                .append(" pairs.</p>\n");
        coverage(h, r);
        h.append("<div class=\"scroll\"><table><thead><tr><th class=\"l\">error</th>")
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
        return h.toString();
    }

    /** Coverage, the longest stretch without an estimate pose, and the report's warnings, as the report gives them. */
    private static void coverage(StringBuilder h, EvaluationReport r) {
        EvaluationReport.CoverageInfo c = r.coverage();
        String unit = "frames".equals(r.timeBase()) ? " frames" : " s";
        if (c != null) {
            h.append("<p>coverage ").append(String.format(Locale.ROOT, "%.1f", 100 * c.fraction()))
                    .append(" % of the reference's ").append(ms(c.referenceSpanS()))
                    .append(unit).append("; longest stretch without an estimate pose ")
                    .append(ms(c.longestGapS())).append(unit).append(" from ")
                    .append(ms(c.longestGapStartS())).append(unit)
                    .append(" (reference clock); ").append(ms(c.uncoveredS()))
                    .append(unit).append(" uncovered in all.</p>\n");
        }
        if (!r.warnings().isEmpty()) {
            h.append("<div class=\"warn\"><b>Warnings</b><ul>\n");
            for (EvaluationReport.Warning w : r.warnings()) {
                h.append("<li><code>").append(SvgCanvas.escape(w.code())).append("</code>: ")
                        .append(SvgCanvas.escape(w.message())).append("</li>\n");
            }
            h.append("</ul></div>\n");
        }
    }

    /** @return a time to the millisecond, without trailing zeros (1300, 8.25, 1305.031) */
    private static String ms(double v) {
        return java.math.BigDecimal.valueOf(Math.round(v * 1000) / 1000.0).stripTrailingZeros().toPlainString();
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
