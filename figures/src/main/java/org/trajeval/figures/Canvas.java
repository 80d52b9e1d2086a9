package org.trajeval.figures;

/**
 * The few drawing operations a figure needs, in pixels (origin top left). Three backends:
 * {@link SvgCanvas} and {@link PdfCanvas} (vector, for papers) and {@link RasterCanvas} (PNG).
 */
interface Canvas {
    /** Text anchor. */
    enum Anchor { START, MIDDLE, END }

    void polyline(double[] x, double[] y, int n, int rgb, float width, boolean dashed);

    /** Fills a closed polygon. */
    void polygon(double[] x, double[] y, int n, int rgb, double opacity);

    void rect(double x, double y, double w, double h, int fillRgb, double fillOpacity, int strokeRgb);

    void marker(double x, double y, double size, Layer.Shape shape, int rgb);

    void text(double x, double y, String s, double size, Anchor anchor, boolean vertical, boolean bold);

    /** Limits drawing to the rectangle until {@link #unclip}. */
    void clip(double x, double y, double w, double h);

    void unclip();
}
