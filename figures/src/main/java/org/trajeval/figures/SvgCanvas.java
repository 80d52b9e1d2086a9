package org.trajeval.figures;

import java.util.Locale;

/** Writes SVG 1.1 text: polylines, rectangles and text, one clip path for the plot area. */
final class SvgCanvas implements Canvas {
    private final StringBuilder s = new StringBuilder(1 << 16);
    private int clips;
    private boolean clipped;

    SvgCanvas(int width, int height) {
        s.append("<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"").append(width).append("\" height=\"")
                .append(height).append("\" viewBox=\"0 0 ").append(width).append(' ').append(height)
                .append("\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n")
                .append("<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n");
    }

    @Override
    public void polyline(double[] x, double[] y, int n, int rgb, float width, boolean dashed) {
        s.append("<polyline fill=\"none\" stroke=\"").append(hex(rgb)).append("\" stroke-width=\"").append(num(width))
                .append("\" stroke-linejoin=\"round\"").append(dashed ? " stroke-dasharray=\"6 4\"" : "")
                .append(" points=\"");
        for (int i = 0; i < n; i++) {
            s.append(i == 0 ? "" : " ").append(num(x[i])).append(',').append(num(y[i]));
        }
        s.append("\"/>\n");
    }

    @Override
    public void polygon(double[] x, double[] y, int n, int rgb, double opacity) {
        s.append("<polygon fill=\"").append(hex(rgb)).append("\" fill-opacity=\"").append(num(opacity))
                .append("\" stroke=\"none\" points=\"");
        for (int i = 0; i < n; i++) {
            s.append(i == 0 ? "" : " ").append(num(x[i])).append(',').append(num(y[i]));
        }
        s.append("\"/>\n");
    }

    @Override
    public void rect(double x, double y, double w, double h, int fillRgb, double fillOpacity, int strokeRgb) {
        s.append("<rect x=\"").append(num(x)).append("\" y=\"").append(num(y)).append("\" width=\"").append(num(w))
                .append("\" height=\"").append(num(h)).append("\" fill=\"")
                .append(fillRgb < 0 ? "none" : hex(fillRgb)).append('"');
        if (fillRgb >= 0 && fillOpacity < 1) {
            s.append(" fill-opacity=\"").append(num(fillOpacity)).append('"');
        }
        if (strokeRgb >= 0) {
            s.append(" stroke=\"").append(hex(strokeRgb)).append("\" stroke-width=\"1\"");
        }
        s.append("/>\n");
    }

    @Override
    public void marker(double x, double y, double size, Layer.Shape shape, int rgb) {
        if (shape == Layer.Shape.CIRCLE) {
            s.append("<circle cx=\"").append(num(x)).append("\" cy=\"").append(num(y)).append("\" r=\"")
                    .append(num(size / 2)).append("\" fill=\"").append(hex(rgb)).append("\" stroke=\"#000000\"/>\n");
        } else {
            rect(x - size / 2, y - size / 2, size, size, rgb, 1, 0x000000);
        }
    }

    @Override
    public void text(double x, double y, String t, double size, Anchor anchor, boolean vertical, boolean bold) {
        s.append("<text x=\"").append(num(x)).append("\" y=\"").append(num(y)).append("\" font-size=\"")
                .append(num(size)).append("\" text-anchor=\"").append(switch (anchor) {
                    case START -> "start";
                    case MIDDLE -> "middle";
                    case END -> "end";
                }).append('"').append(bold ? " font-weight=\"bold\"" : "");
        if (vertical) {
            s.append(" transform=\"rotate(-90 ").append(num(x)).append(' ').append(num(y)).append(")\"");
        }
        s.append('>').append(escape(t)).append("</text>\n");
    }

    @Override
    public void clip(double x, double y, double w, double h) {
        clips++;
        s.append("<clipPath id=\"c").append(clips).append("\"><rect x=\"").append(num(x)).append("\" y=\"")
                .append(num(y)).append("\" width=\"").append(num(w)).append("\" height=\"").append(num(h))
                .append("\"/></clipPath>\n<g clip-path=\"url(#c").append(clips).append(")\">\n");
        clipped = true;
    }

    @Override
    public void unclip() {
        if (clipped) {
            s.append("</g>\n");
            clipped = false;
        }
    }

    /** @return the document */
    String finish() {
        unclip();
        return s.append("</svg>\n").toString();
    }

    private static String hex(int rgb) {
        return String.format(Locale.ROOT, "#%06x", rgb & 0xffffff);
    }

    private static String num(double v) {
        double r = Math.round(v * 10) / 10.0;
        return r == Math.rint(r) ? Long.toString((long) r) : Double.toString(r);
    }

    static String escape(String t) {
        StringBuilder b = new StringBuilder(t.length());
        for (char c : t.toCharArray()) {
            switch (c) {
                case '&' -> b.append("&amp;");
                case '<' -> b.append("&lt;");
                case '>' -> b.append("&gt;");
                case '"' -> b.append("&quot;");
                default -> b.append(c < 0x20 ? ' ' : c);
            }
        }
        return b.toString();
    }
}
