package org.trajeval.figures;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.zip.Deflater;

/**
 * Writes one PDF 1.4 page of vector drawing, by hand (no PDF library): paths stroked and filled
 * in RGB, opacity through ExtGState ({@code /ca}), text in the standard Type 1 fonts Helvetica
 * and Helvetica-Bold (WinAnsiEncoding, not embedded: every PDF reader has them), the content
 * stream Flate-compressed. One canvas unit is one point (1/72 in), so a 760 x 440 figure is a
 * 26.8 x 15.5 cm page that LaTeX's {@code \includegraphics} scales without loss. The output
 * depends on the drawing only (no dates), so the same figure gives the same bytes.
 *
 * <p>Coordinates: the canvas has its origin at the top left with y down, PDF at the bottom left
 * with y up; the page's first operator {@code 1 0 0 -1 0 H cm} flips y once, and text, which
 * would then be upside down, gets the text matrix {@code 1 0 0 -1 x y} (horizontal) or
 * {@code 0 -1 -1 0 x y} (vertical, reading upwards as SVG's {@code rotate(-90)}).
 */
final class PdfCanvas implements Canvas {
    /**
     * Advance widths (1/1000 em) of Helvetica and Helvetica-Bold for codes 32..126, from Adobe's
     * AFM files (as shipped in groff's {@code font/devps/HR} and {@code HB}), quotesingle and
     * grave as WinAnsiEncoding places them.
     */
    private static final int[] HELVETICA = {278, 278, 355, 556, 556, 889, 667, 191, 333, 333, 389, 584, 278, 333,
        278, 278, 556, 556, 556, 556, 556, 556, 556, 556, 556, 556, 278, 278, 584, 584, 584, 556, 1015, 667, 667,
        722, 722, 667, 611, 778, 722, 278, 500, 667, 556, 833, 722, 778, 667, 778, 722, 667, 611, 722, 667, 944, 667,
        667, 611, 278, 278, 278, 469, 556, 333, 556, 556, 500, 556, 556, 278, 556, 556, 222, 222, 500, 222, 833, 556,
        556, 556, 556, 333, 500, 278, 556, 500, 722, 500, 500, 500, 334, 260, 334, 584};
    private static final int[] HELVETICA_BOLD = {278, 333, 474, 556, 556, 889, 722, 238, 333, 333, 389, 584, 278,
        333, 278, 278, 556, 556, 556, 556, 556, 556, 556, 556, 556, 556, 333, 333, 584, 584, 584, 611, 975, 722, 722,
        722, 722, 667, 611, 778, 722, 278, 556, 722, 611, 833, 722, 778, 667, 778, 722, 667, 611, 722, 667, 944, 667,
        667, 611, 333, 278, 333, 584, 556, 333, 556, 611, 556, 611, 556, 333, 611, 611, 278, 278, 556, 278, 889, 611,
        611, 611, 611, 389, 556, 333, 611, 556, 778, 556, 556, 500, 389, 280, 389, 584};
    private static final int TEXT = 0x222222;
    /** Bezier handle length of a quarter circle, 4/3 (sqrt 2 - 1). */
    private static final double KAPPA = 0.5522847498;

    private final int width;
    private final int height;
    private final StringBuilder s = new StringBuilder(1 << 16);
    private final Map<String, String> opacities = new LinkedHashMap<>();
    private boolean clipped;

    PdfCanvas(int width, int height) {
        this.width = width;
        this.height = height;
        s.append("1 0 0 -1 0 ").append(height).append(" cm\n1 1 1 rg 0 0 ").append(width).append(' ').append(height)
                .append(" re f\n");
    }

    @Override
    public void polyline(double[] x, double[] y, int n, int rgb, float lineWidth, boolean dashed) {
        if (n < 2) {
            return;
        }
        colour(rgb, "RG");
        s.append(num(lineWidth)).append(" w ").append(dashed ? "0 J 1 j [6 4] 0 d\n" : "1 J 1 j [] 0 d\n");
        path(x, y, n);
        s.append("S\n");
    }

    @Override
    public void polygon(double[] x, double[] y, int n, int rgb, double opacity) {
        if (n < 3) {
            return;
        }
        s.append("q ").append(opacity(opacity)).append(" gs ");
        colour(rgb, "rg");
        path(x, y, n);
        s.append("h f Q\n");
    }

    @Override
    public void rect(double x, double y, double w, double h, int fillRgb, double fillOpacity, int strokeRgb) {
        String r = num(x) + " " + num(y) + " " + num(w) + " " + num(h) + " re ";
        if (fillRgb >= 0) {
            s.append("q ").append(fillOpacity < 1 ? opacity(fillOpacity) + " gs " : "");
            colour(fillRgb, "rg");
            s.append(r).append("f Q\n");
        }
        if (strokeRgb >= 0) {
            colour(strokeRgb, "RG");
            s.append("1 w [] 0 d ").append(r).append("S\n");
        }
    }

    @Override
    public void marker(double x, double y, double size, Layer.Shape shape, int rgb) {
        colour(rgb, "rg");
        colour(0x000000, "RG");
        s.append("1 w [] 0 d ");
        double r = size / 2;
        if (shape == Layer.Shape.CIRCLE) {
            double k = KAPPA * r;
            s.append(num(x + r)).append(' ').append(num(y)).append(" m ");
            curve(x + r, y + k, x + k, y + r, x, y + r);
            curve(x - k, y + r, x - r, y + k, x - r, y);
            curve(x - r, y - k, x - k, y - r, x, y - r);
            curve(x + k, y - r, x + r, y - k, x + r, y);
            s.append("h B\n");
        } else {
            s.append(num(x - r)).append(' ').append(num(y - r)).append(' ').append(num(size)).append(' ')
                    .append(num(size)).append(" re B\n");
        }
    }

    @Override
    public void text(double x, double y, String t, double size, Anchor anchor, boolean vertical, boolean bold) {
        byte[] codes = winAnsi(t);
        double w = width(codes, bold) * size / 1000.0;
        double shift = switch (anchor) {
            case START -> 0;
            case MIDDLE -> -w / 2;
            case END -> -w;
        };
        colour(TEXT, "rg");
        s.append("BT /").append(bold ? "F2 " : "F1 ").append(num(size)).append(" Tf ");
        if (vertical) { // text runs upwards from (x, y + ...): the shift moves along the text's direction
            s.append("0 -1 -1 0 ").append(num(x)).append(' ').append(num(y - shift));
        } else {
            s.append("1 0 0 -1 ").append(num(x + shift)).append(' ').append(num(y));
        }
        s.append(" Tm (");
        for (byte b : codes) {
            int c = b & 0xff;
            if (c == '(' || c == ')' || c == '\\') {
                s.append('\\').append((char) c);
            } else if (c < 32 || c > 126) {
                s.append(String.format(Locale.ROOT, "\\%03o", c));
            } else {
                s.append((char) c);
            }
        }
        s.append(") Tj ET\n");
    }

    @Override
    public void clip(double x, double y, double w, double h) {
        unclip();
        s.append("q ").append(num(x)).append(' ').append(num(y)).append(' ').append(num(w)).append(' ')
                .append(num(h)).append(" re W n\n");
        clipped = true;
    }

    @Override
    public void unclip() {
        if (clipped) {
            s.append("Q\n");
            clipped = false;
        }
    }

    /** @return the PDF file */
    byte[] finish() {
        unclip();
        byte[] content = deflate(s.toString().getBytes(StandardCharsets.US_ASCII));
        StringBuilder gs = new StringBuilder();
        for (Map.Entry<String, String> e : opacities.entrySet()) {
            gs.append('/').append(e.getValue()).append(" << /Type /ExtGState /ca ").append(e.getKey()).append(" >> ");
        }
        List<byte[]> objects = new ArrayList<>();
        objects.add(ascii("<< /Type /Catalog /Pages 2 0 R >>"));
        objects.add(ascii("<< /Type /Pages /Kids [3 0 R] /Count 1 >>"));
        objects.add(ascii("<< /Type /Page /Parent 2 0 R /MediaBox [0 0 " + width + " " + height + "] /Resources << "
                + "/Font << /F1 4 0 R /F2 5 0 R >> /ExtGState << " + gs + ">> >> /Contents 6 0 R >>"));
        objects.add(ascii("<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica /Encoding /WinAnsiEncoding >>"));
        objects.add(ascii("<< /Type /Font /Subtype /Type1 /BaseFont /Helvetica-Bold /Encoding /WinAnsiEncoding >>"));
        ByteArrayOutputStream stream = new ByteArrayOutputStream(content.length + 64);
        stream.writeBytes(ascii("<< /Length " + content.length + " /Filter /FlateDecode >>\nstream\n"));
        stream.writeBytes(content);
        stream.writeBytes(ascii("\nendstream"));
        objects.add(stream.toByteArray());
        objects.add(ascii("<< /Producer (trajeval) >>"));
        ByteArrayOutputStream out = new ByteArrayOutputStream(content.length + 2048);
        out.writeBytes(ascii("%PDF-1.4\n%\u00e2\u00e3\u00cf\u00d3\n")); // binary marker line
        long[] offsets = new long[objects.size()];
        for (int i = 0; i < objects.size(); i++) {
            offsets[i] = out.size();
            out.writeBytes(ascii((i + 1) + " 0 obj\n"));
            out.writeBytes(objects.get(i));
            out.writeBytes(ascii("\nendobj\n"));
        }
        long xref = out.size();
        StringBuilder x = new StringBuilder("xref\n0 " + (objects.size() + 1) + "\n0000000000 65535 f \n");
        for (long o : offsets) {
            x.append(String.format(Locale.ROOT, "%010d 00000 n \n", o));
        }
        x.append("trailer\n<< /Size ").append(objects.size() + 1).append(" /Root 1 0 R /Info ").append(objects.size())
                .append(" 0 R >>\nstartxref\n").append(xref).append("\n%%EOF\n");
        out.writeBytes(ascii(x.toString()));
        return out.toByteArray();
    }

    /** @return the width of the text in 1/1000 em */
    static int width(byte[] winAnsi, boolean bold) {
        int[] table = bold ? HELVETICA_BOLD : HELVETICA;
        int w = 0;
        for (byte b : winAnsi) {
            int c = b & 0xff;
            w += c >= 32 && c <= 126 ? table[c - 32] : switch (c) {
                case 0x85, 0x97 -> 1000; // ellipsis, em dash
                case 0xb1, 0xd7 -> 584; // plus-minus, multiplication
                case 0xb0 -> 400; // degree
                default -> 556;
            };
        }
        return w;
    }

    /** @return the text in WinAnsiEncoding (Latin-1 plus the few CP1252 extras figures use; others as '?') */
    static byte[] winAnsi(String t) {
        byte[] out = new byte[t.length()];
        for (int i = 0; i < t.length(); i++) {
            char c = t.charAt(i);
            out[i] = (byte) (c < 32 ? ' ' : c <= 126 || (c >= 0xa0 && c <= 0xff) ? c : switch (c) {
                case '\u2026' -> 0x85;
                case '\u2013' -> 0x96;
                case '\u2014' -> 0x97;
                case '\u2212' -> '-';
                default -> '?';
            });
        }
        return out;
    }

    private void path(double[] x, double[] y, int n) {
        s.append(num(x[0])).append(' ').append(num(y[0])).append(" m");
        for (int i = 1; i < n; i++) {
            s.append(i % 8 == 0 ? "\n" : " ").append(num(x[i])).append(' ').append(num(y[i])).append(" l");
        }
        s.append('\n');
    }

    private void curve(double x1, double y1, double x2, double y2, double x3, double y3) {
        s.append(num(x1)).append(' ').append(num(y1)).append(' ').append(num(x2)).append(' ').append(num(y2))
                .append(' ').append(num(x3)).append(' ').append(num(y3)).append(" c ");
    }

    private void colour(int rgb, String op) {
        s.append(unit((rgb >> 16) & 255)).append(' ').append(unit((rgb >> 8) & 255)).append(' ')
                .append(unit(rgb & 255)).append(' ').append(op).append(' ');
    }

    private String opacity(double a) {
        String key = num(Math.max(0, Math.min(1, a)));
        return "/" + opacities.computeIfAbsent(key, k -> "A" + opacities.size());
    }

    private static String unit(int c) {
        return num(c / 255.0);
    }

    /** Two decimals: 1/7200 in, far below any printer's dot. */
    static String num(double v) {
        long r = Math.round(v * 100);
        String sign = r < 0 ? "-" : "";
        long a = Math.abs(r);
        long whole = a / 100;
        int frac = (int) (a % 100);
        if (frac == 0) {
            return sign + whole;
        }
        return sign + whole + (frac % 10 == 0 ? "." + frac / 10 : frac < 10 ? ".0" + frac : "." + frac);
    }

    private static byte[] ascii(String t) {
        return t.getBytes(StandardCharsets.ISO_8859_1);
    }

    private static byte[] deflate(byte[] in) {
        Deflater d = new Deflater(Deflater.BEST_COMPRESSION);
        d.setInput(in);
        d.finish();
        ByteArrayOutputStream out = new ByteArrayOutputStream(in.length / 4 + 64);
        byte[] buf = new byte[1 << 14];
        while (!d.finished()) {
            out.write(buf, 0, d.deflate(buf));
        }
        d.end();
        return out.toByteArray();
    }
}
