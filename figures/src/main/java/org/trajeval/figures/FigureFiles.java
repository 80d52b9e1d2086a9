package org.trajeval.figures;

import java.nio.file.Path;
import org.trajeval.core.report.ReportJson;

/** Renders a {@link Figure} as SVG and PDF (vector, for papers) and PNG (for pages and READMEs). */
public final class FigureFiles {
    private FigureFiles() {
    }

    /** @return the figure as an SVG document */
    public static String svg(Figure f) {
        SvgCanvas c = new SvgCanvas(FigurePainter.WIDTH, FigurePainter.HEIGHT);
        FigurePainter.paint(f, c);
        return c.finish();
    }

    /** @return the figure as PNG bytes, {@code scale} pixels per layout pixel */
    public static byte[] png(Figure f, double scale) {
        RasterCanvas c = new RasterCanvas(FigurePainter.WIDTH, FigurePainter.HEIGHT, scale);
        FigurePainter.paint(f, c);
        return c.png();
    }

    /** @return the figure as a one-page vector PDF (1.4; points as layout pixels, Helvetica text) */
    public static byte[] pdf(Figure f) {
        PdfCanvas c = new PdfCanvas(FigurePainter.WIDTH, FigurePainter.HEIGHT);
        FigurePainter.paint(f, c);
        return c.finish();
    }

    /** Writes {@code NAME.svg} and {@code NAME.png} into {@code dir} (each atomically). */
    public static void write(Figure f, Path dir) {
        ReportJson.writeAtomically(dir.resolve(f.name() + ".svg"), svg(f));
        ReportJson.writeAtomically(dir.resolve(f.name() + ".png"), png(f, 1.0));
    }
}
