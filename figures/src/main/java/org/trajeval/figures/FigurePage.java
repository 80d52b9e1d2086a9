package org.trajeval.figures;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.Base64;
import java.util.List;
import java.util.Set;
import org.trajeval.core.report.ReportJson;

/**
 * A folder of figures: every figure as {@code NAME.svg} and {@code NAME.png} (or the formats
 * asked for, {@code NAME.pdf} among them), and
 * {@code index.html}, one self-contained page (figures as SVG data URIs, inline CSS, no script,
 * no network fetch) with a heading, an HTML block of numbers, and the figures.
 */
public final class FigurePage {
    /** File name of the page. */
    public static final String INDEX = "index.html";

    private FigurePage() {
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

    /**
     * @param title page title (plain text)
     * @param numbers HTML shown above the figures (escaped by the caller)
     */
    public static void write(String title, String numbers, List<Figure> figures, Path dir, Progress progress) {
        write(title, numbers, figures, dir, FigureFormat.DEFAULT, progress);
    }

    /**
     * As above, each figure in the given formats (the page itself shows the SVG, embedded).
     *
     * @throws IllegalArgumentException on an empty set of formats
     */
    public static void write(String title, String numbers, List<Figure> figures, Path dir,
            Set<FigureFormat> formats, Progress progress) {
        if (formats.isEmpty()) {
            throw new IllegalArgumentException("at least one figure format is needed");
        }
        StringBuilder body = new StringBuilder();
        int done = 0;
        for (Figure f : figures) {
            String svg = FigureFiles.svg(f);
            StringBuilder links = new StringBuilder();
            for (FigureFormat format : formats) {
                Path file = dir.resolve(f.name() + "." + format.extension());
                switch (format) {
                    case SVG -> ReportJson.writeAtomically(file, svg);
                    case PNG -> ReportJson.writeAtomically(file, FigureFiles.png(f, 1.0));
                    case PDF -> ReportJson.writeAtomically(file, FigureFiles.pdf(f));
                    default -> throw new IllegalStateException("unknown format " + format);
                }
                links.append(links.length() == 0 ? "" : " &middot; ").append("<a href=\"").append(f.name()).append('.')
                        .append(format.extension()).append("\">").append(format.name()).append("</a>");
            }
            body.append("<figure><img src=\"data:image/svg+xml;base64,")
                    .append(Base64.getEncoder().encodeToString(svg.getBytes(StandardCharsets.UTF_8)))
                    .append("\" alt=\"").append(esc(f.title())).append("\" width=\"").append(FigurePainter.WIDTH)
                    .append("\" height=\"").append(FigurePainter.HEIGHT).append("\"><figcaption>").append(links)
                    .append("</figcaption></figure>\n");
            progress.done(++done, figures.size());
        }
        String page = "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
                + "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" + esc(title)
                + "</title>\n<style>\nbody{font-family:system-ui,sans-serif;margin:1.5em auto;max-width:1560px;"
                + "color:#222;padding:0 1em}\n.scroll{overflow-x:auto}table{border-collapse:collapse;"
                + "margin:0.5em 0 1em}th,td{border:1px solid #ccc;padding:3px 8px;text-align:right;"
                + "font-variant-numeric:tabular-nums}th{background:#f3f3f3}td.l,th.l{text-align:left}\n"
                + ".figs{display:flex;flex-wrap:wrap;gap:8px}figure{margin:0}"
                + "figure img{max-width:100%;height:auto;border:1px solid #ddd}"
                + "figcaption{font-size:0.85em;color:#666}\n"
                + ".warn{border-left:4px solid #e6a100;background:#fff8e6;padding:4px 10px;margin:0.5em 0}\n</style></head><body>\n<h1>" + esc(title) + "</h1>\n"
                + numbers + "<div class=\"figs\">\n" + body + "</div>\n</body></html>\n";
        ReportJson.writeAtomically(dir.resolve(INDEX), page);
    }

    /** @return text escaped for HTML and SVG (control characters become spaces) */
    public static String esc(String s) {
        return s == null ? "" : SvgCanvas.escape(s);
    }
}
