package org.trajeval.cli;

import java.util.Locale;
import org.trajeval.store.Trend;

/**
 * The trend as one self-contained HTML page (no script, no fetch): per slice an inline SVG of the
 * bucket means with their intervals, and the table. The figure's data (points, ranges) is the
 * {@link Trend.Result}; this class only draws it.
 */
final class TrendPage {
    private static final int W = 640;
    private static final int H = 160;
    private static final int PAD = 30;

    private TrendPage() {
    }

    static String html(Trend.Result r) {
        StringBuilder b = new StringBuilder("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>")
                .append(esc("trend of " + r.metric() + " by " + r.by())).append("</title><style>body{font-family:"
                        + "sans-serif;margin:2em}table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:"
                        + "2px 6px;text-align:right}.worse{color:#b00;font-weight:bold}</style></head><body>\n");
        b.append("<h1>").append(esc(r.metric())).append(" by ").append(esc(r.by())).append("</h1>\n<p>Per ")
                .append(r.bucket().name().toLowerCase(Locale.ROOT)).append(": mean and ")
                .append(String.format(Locale.ROOT, "%.0f %%", 100 * r.confidence()))
                .append(" t-interval. A slice is flagged when its latest bucket is worse than its history (Welch "
                        + "one-sided, Holm across slices).</p>\n");
        for (Trend.Slice s : r.slices()) {
            b.append("<h2").append(s.flagged() ? " class=\"worse\"" : "").append(">").append(esc(s.slice()))
                    .append(s.flagged() ? " &#8212; WORSE" : "").append("</h2>\n");
            b.append(svg(s)).append('\n');
            b.append("<table><tr><th>bucket</th><th>n</th><th>mean</th><th>interval</th></tr>\n");
            for (Trend.Point p : s.points()) {
                b.append("<tr><td>").append(esc(p.bucket())).append("</td><td>").append(p.n()).append("</td><td>")
                        .append(TrendCommand.num(p.mean())).append("</td><td>")
                        .append(p.interval() == null ? "-" : "[" + TrendCommand.num(p.interval().lower()) + ", "
                                + TrendCommand.num(p.interval().upper()) + "]")
                        .append("</td></tr>\n");
            }
            b.append("</table>\n<p>latest ").append(TrendCommand.num(s.latest().mean())).append(" vs history ")
                    .append(TrendCommand.num(s.historyMean())).append(": p ").append(TrendCommand.num(s.pValue()))
                    .append(", Holm ").append(TrendCommand.num(s.adjustedP())).append("</p>\n");
        }
        return b.append("</body></html>\n").toString();
    }

    private static String svg(Trend.Slice s) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (Trend.Point p : s.points()) {
            lo = Math.min(lo, p.interval() == null ? p.mean() : p.interval().lower());
            hi = Math.max(hi, p.interval() == null ? p.mean() : p.interval().upper());
        }
        if (!(hi > lo)) {
            hi = lo + 1;
        }
        int k = s.points().size();
        StringBuilder b = new StringBuilder("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + W + "\" height=\""
                + H + "\"><rect width=\"100%\" height=\"100%\" fill=\"#fafafa\"/>");
        StringBuilder line = new StringBuilder();
        for (int i = 0; i < k; i++) {
            Trend.Point p = s.points().get(i);
            double x = PAD + (k == 1 ? 0.5 : (double) i / (k - 1)) * (W - 2 * PAD);
            if (p.interval() != null) {
                b.append(String.format(Locale.ROOT, "<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\" "
                        + "stroke=\"#999\"/>", x, x, y(p.interval().lower(), lo, hi), y(p.interval().upper(), lo, hi)));
            }
            line.append(String.format(Locale.ROOT, "%.1f,%.1f ", x, y(p.mean(), lo, hi)));
        }
        b.append("<polyline fill=\"none\" stroke=\"#1f77b4\" stroke-width=\"2\" points=\"").append(line.toString().strip())
                .append("\"/>");
        b.append(String.format(Locale.ROOT, "<text x=\"2\" y=\"12\" font-size=\"10\">%s</text><text x=\"2\" y=\"%d\" "
                + "font-size=\"10\">%s</text></svg>", TrendCommand.num(hi), H - 4, TrendCommand.num(lo)));
        return b.toString();
    }

    private static double y(double v, double lo, double hi) {
        return H - PAD / 2.0 - (v - lo) / (hi - lo) * (H - PAD);
    }

    private static String esc(String s) {
        return s.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace("\"", "&quot;");
    }
}
