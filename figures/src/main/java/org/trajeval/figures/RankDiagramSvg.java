package org.trajeval.figures;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.RankedMethod;
import org.trajeval.core.report.SuiteReport.Ranking;

/**
 * Draws an average-rank ("critical difference") diagram as SVG from a {@link Ranking} (the data
 * lives in the report; this class only draws it). An axis of ranks 1..k (1 = best, on the left);
 * each method hangs from its average rank, the better half labelled on the left, the rest on the
 * right; a thick bar joins the methods of each group, i.e. methods no pair of which differs
 * significantly by the Holm-adjusted pairwise tests. Plain SVG 1.1, no script, no font file.
 */
public final class RankDiagramSvg {
    private static final double WIDTH = 640;
    private static final double TEXT = 150;
    private static final double AXIS_Y = 56;
    private static final double ROW = 20;

    private RankDiagramSvg() {
    }

    /** @return the file name of a metric's diagram */
    public static String fileName(String metric) {
        return "ranks_" + metric.replaceAll("[^A-Za-z0-9_.-]", "_") + ".svg";
    }

    /** Writes one SVG per ranking that has average ranks into {@code dir} (atomically, one by one). */
    public static void writeAll(SuiteReport report, Path dir) {
        for (Ranking r : report.rankings()) {
            if (drawable(r)) {
                ReportJson.writeAtomically(dir.resolve(fileName(r.metric())), render(r));
            }
        }
    }

    /** @return true when the ranking has average ranks to draw */
    public static boolean drawable(Ranking r) {
        return r.methods().size() >= 2 && r.methods().stream().allMatch(m -> m.averageRank() != null);
    }

    /**
     * @return the SVG document
     * @throws IllegalArgumentException when the ranking has no average ranks
     */
    public static String render(Ranking r) {
        if (!drawable(r)) {
            throw new IllegalArgumentException("no average ranks to draw for " + r.metric());
        }
        int k = r.methods().size();
        List<RankedMethod> sorted = new ArrayList<>(r.methods());
        sorted.sort(Comparator.comparingDouble(RankedMethod::averageRank));
        int left = (k + 1) / 2;
        int rows = Math.max(left, k - left);
        double groupsHeight = r.groups().size() * 7.0;
        double firstRow = AXIS_Y + 18 + groupsHeight;
        double height = firstRow + rows * ROW + 24;
        StringBuilder s = new StringBuilder(2048);
        s.append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(f(WIDTH)).append("\" height=\"")
                .append(f(height)).append("\" viewBox=\"0 0 ").append(f(WIDTH)).append(' ').append(f(height))
                .append("\" font-family=\"sans-serif\" font-size=\"12\">\n");
        s.append("<title>average rank on ").append(esc(r.metric())).append("</title>\n");
        s.append("<text x=\"").append(f(WIDTH / 2)).append("\" y=\"16\" text-anchor=\"middle\">average rank on ")
                .append(esc(r.metric())).append(" (1 = best, ").append(r.better()).append(" is better) over ")
                .append(r.n()).append(" sequences</text>\n");
        s.append("<line x1=\"").append(f(x(1, k))).append("\" y1=\"").append(f(AXIS_Y)).append("\" x2=\"")
                .append(f(x(k, k))).append("\" y2=\"").append(f(AXIS_Y)).append("\" stroke=\"black\"/>\n");
        for (int t = 1; t <= k; t++) {
            s.append("<line x1=\"").append(f(x(t, k))).append("\" y1=\"").append(f(AXIS_Y - 5)).append("\" x2=\"")
                    .append(f(x(t, k))).append("\" y2=\"").append(f(AXIS_Y)).append("\" stroke=\"black\"/>")
                    .append("<text x=\"").append(f(x(t, k))).append("\" y=\"").append(f(AXIS_Y - 9))
                    .append("\" text-anchor=\"middle\">").append(t).append("</text>\n");
        }
        for (int g = 0; g < r.groups().size(); g++) {
            List<String> members = r.groups().get(g);
            double lo = rankOf(sorted, members.get(0));
            double hi = rankOf(sorted, members.get(members.size() - 1));
            double y = AXIS_Y + 10 + g * 7.0;
            s.append("<line class=\"group\" x1=\"").append(f(x(lo, k) - 4)).append("\" y1=\"").append(f(y))
                    .append("\" x2=\"").append(f(x(hi, k) + 4)).append("\" y2=\"").append(f(y))
                    .append("\" stroke=\"#c0392b\" stroke-width=\"4\" stroke-linecap=\"round\"/>\n");
        }
        for (int i = 0; i < k; i++) {
            RankedMethod m = sorted.get(i);
            boolean onLeft = i < left;
            int row = onLeft ? i : k - 1 - i;
            double y = firstRow + row * ROW;
            double xr = x(m.averageRank(), k);
            double end = onLeft ? TEXT - 8 : WIDTH - TEXT + 8;
            s.append("<polyline class=\"method\" points=\"").append(f(xr)).append(',').append(f(AXIS_Y)).append(' ')
                    .append(f(xr)).append(',').append(f(y)).append(' ').append(f(end)).append(',').append(f(y))
                    .append("\" fill=\"none\" stroke=\"#555\"/>");
            s.append("<text x=\"").append(f(onLeft ? end - 4 : end + 4)).append("\" y=\"").append(f(y + 4))
                    .append("\" text-anchor=\"").append(onLeft ? "end" : "start").append("\">").append(esc(m.name()))
                    .append(" (").append(String.format(Locale.ROOT, "%.2f", m.averageRank())).append(")</text>\n");
        }
        s.append("<text x=\"").append(f(WIDTH / 2)).append("\" y=\"").append(f(height - 6))
                .append("\" text-anchor=\"middle\" fill=\"#666\" font-size=\"10\">bars: no significant difference, ")
                .append(esc(r.family())).append(", alpha = ").append(String.format(Locale.ROOT, "%.3g", r.alpha()))
                .append("</text>\n</svg>\n");
        return s.toString();
    }

    private static double rankOf(List<RankedMethod> sorted, String name) {
        return sorted.stream().filter(m -> m.name().equals(name)).findFirst().orElseThrow().averageRank();
    }

    /** @return the x coordinate of rank {@code r} on an axis of ranks 1..k */
    static double x(double r, int k) {
        return TEXT + (r - 1.0) / Math.max(1, k - 1) * (WIDTH - 2 * TEXT);
    }

    private static String f(double v) {
        return String.format(Locale.ROOT, "%.1f", v);
    }

    private static String esc(String s) {
        return SuiteHtml.esc(s).replace("'", "&apos;");
    }
}
