package org.trajeval.figures;

import java.awt.BasicStroke;
import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.geom.AffineTransform;
import java.awt.geom.Ellipse2D;
import java.awt.geom.Path2D;
import java.awt.geom.Rectangle2D;
import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import javax.imageio.ImageIO;

/** Draws on a Java2D image (headless) and encodes it as PNG. */
final class RasterCanvas implements Canvas {
    private final BufferedImage image;
    private final Graphics2D g;
    private final double scale;

    /** @param scale pixels per canvas unit (2 for sharp images on high-density screens) */
    RasterCanvas(int width, int height, double scale) {
        this.scale = scale;
        image = new BufferedImage((int) Math.round(width * scale), (int) Math.round(height * scale),
                BufferedImage.TYPE_INT_RGB);
        g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setRenderingHint(RenderingHints.KEY_STROKE_CONTROL, RenderingHints.VALUE_STROKE_PURE);
        g.scale(scale, scale);
        g.setColor(Color.WHITE);
        g.fillRect(0, 0, width, height);
    }

    @Override
    public void polyline(double[] x, double[] y, int n, int rgb, float width, boolean dashed) {
        if (n < 2) {
            return;
        }
        Path2D.Double p = new Path2D.Double(Path2D.WIND_NON_ZERO, n);
        p.moveTo(x[0], y[0]);
        for (int i = 1; i < n; i++) {
            p.lineTo(x[i], y[i]);
        }
        g.setColor(new Color(rgb));
        // bevel joins on long lines: the same pixels at 1-2 px widths, a third less stroking work
        int join = n > 64 ? BasicStroke.JOIN_BEVEL : BasicStroke.JOIN_ROUND;
        g.setStroke(dashed ? new BasicStroke(width, BasicStroke.CAP_BUTT, join, 10f, new float[] {6f, 4f}, 0f)
                : new BasicStroke(width, BasicStroke.CAP_ROUND, join));
        g.draw(p);
    }

    @Override
    public void polygon(double[] x, double[] y, int n, int rgb, double opacity) {
        if (n < 3) {
            return;
        }
        Path2D.Double p = new Path2D.Double(Path2D.WIND_NON_ZERO, n);
        p.moveTo(x[0], y[0]);
        for (int i = 1; i < n; i++) {
            p.lineTo(x[i], y[i]);
        }
        p.closePath();
        g.setColor(new Color((rgb >> 16) & 255, (rgb >> 8) & 255, rgb & 255, (int) Math.round(255 * opacity)));
        g.fill(p);
    }

    @Override
    public void rect(double x, double y, double w, double h, int fillRgb, double fillOpacity, int strokeRgb) {
        Rectangle2D.Double r = new Rectangle2D.Double(x, y, w, h);
        if (fillRgb >= 0) {
            g.setColor(new Color((fillRgb >> 16) & 255, (fillRgb >> 8) & 255, fillRgb & 255,
                    (int) Math.round(255 * fillOpacity)));
            g.fill(r);
        }
        if (strokeRgb >= 0) {
            g.setColor(new Color(strokeRgb));
            g.setStroke(new BasicStroke(1f));
            g.draw(r);
        }
    }

    @Override
    public void marker(double x, double y, double size, Layer.Shape shape, int rgb) {
        java.awt.Shape s = shape == Layer.Shape.CIRCLE ? new Ellipse2D.Double(x - size / 2, y - size / 2, size, size)
                : new Rectangle2D.Double(x - size / 2, y - size / 2, size, size);
        g.setColor(new Color(rgb));
        g.fill(s);
        g.setColor(Color.BLACK);
        g.setStroke(new BasicStroke(1f));
        g.draw(s);
    }

    @Override
    public void text(double x, double y, String t, double size, Anchor anchor, boolean vertical, boolean bold) {
        Font f = new Font(Font.SANS_SERIF, bold ? Font.BOLD : Font.PLAIN, 1).deriveFont((float) size);
        g.setFont(f);
        g.setColor(new Color(0x222222));
        double w = g.getFontMetrics().getStringBounds(t, g).getWidth();
        double dx = switch (anchor) {
            case START -> 0;
            case MIDDLE -> -w / 2;
            case END -> -w;
        };
        AffineTransform saved = g.getTransform();
        g.translate(x, y);
        if (vertical) {
            g.rotate(-Math.PI / 2);
        }
        g.drawString(t, (float) dx, 0f);
        g.setTransform(saved);
    }

    @Override
    public void clip(double x, double y, double w, double h) {
        g.setClip(new Rectangle2D.Double(x, y, w, h));
    }

    @Override
    public void unclip() {
        g.setClip(null);
    }

    /** @return the PNG bytes */
    byte[] png() {
        g.dispose();
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try {
            ImageIO.write(image, "png", out);
        } catch (IOException e) {
            throw new UncheckedIOException("PNG encoding failed", e);
        }
        return out.toByteArray();
    }

    /** @return pixels per canvas unit */
    double scale() {
        return scale;
    }
}
