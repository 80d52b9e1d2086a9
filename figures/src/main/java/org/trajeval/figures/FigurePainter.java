package org.trajeval.figures;

import java.util.List;

/**
 * Lays a {@link Figure} out and draws it on a {@link Canvas}: title, plot frame, grid, ticks,
 * axis labels, the layers clipped to the plot area, the legend outside the data (right), and the
 * colour bar. The same code draws SVG and PNG.
 */
final class FigurePainter {
    /** Canvas width (px). */
    static final int WIDTH = 760;
    /** Canvas height (px). */
    static final int HEIGHT = 440;
    private static final int LEFT = 78;
    private static final int TOP = 40;
    private static final int BOTTOM = 52;
    private static final double FONT = 12;
    private static final int GRID = 0xe4e4e4;
    private static final int FRAME = 0x444444;
    private static final int COLOUR_LEVELS = 64;
    /** Points closer than this to the last drawn one, in both directions, are not drawn (px). */
    static final double THIN_PX = 0.5;

    private FigurePainter() {
    }

    static void paint(Figure f, Canvas c) {
        List<Layer> labelled = f.layers().stream().filter(l -> l.label() != null).toList();
        int legendWidth = 0;
        for (Layer l : labelled) {
            legendWidth = Math.max(legendWidth, (int) (l.label().length() * FONT * 0.6) + 44);
        }
        int right = 16 + Math.min(legendWidth, 240) + (f.colour() != null ? 84 : 0);
        double px = LEFT;
        double py = TOP;
        double pw = WIDTH - LEFT - right;
        double ph = HEIGHT - TOP - BOTTOM;
        Axis ax = f.x();
        Axis ay = f.y();
        if (f.equalScales()) {
            double perPx = Math.max((ax.max() - ax.min()) / pw, (ay.max() - ay.min()) / ph);
            double cx = 0.5 * (ax.min() + ax.max());
            double cy = 0.5 * (ay.min() + ay.max());
            ax = ax.withRange(cx - perPx * pw / 2, cx + perPx * pw / 2);
            ay = ay.withRange(cy - perPx * ph / 2, cy + perPx * ph / 2);
        }
        Mapping m = new Mapping(ax, ay, px, py, pw, ph);

        c.text(WIDTH / 2.0, 24, f.title(), 14, Canvas.Anchor.MIDDLE, false, true);
        grid(c, m);
        c.clip(px, py, pw, ph);
        for (Layer l : f.layers()) {
            layer(c, m, l, f.colour());
        }
        c.unclip();
        c.rect(px, py, pw, ph, -1, 1, FRAME);
        c.text(px + pw / 2, HEIGHT - 12, ax.label(), FONT, Canvas.Anchor.MIDDLE, false, false);
        c.text(18, py + ph / 2, ay.label(), FONT, Canvas.Anchor.MIDDLE, true, false);
        double lx = px + pw + 14 + (f.colour() != null ? 84 : 0);
        double ly = py + 6;
        for (Layer l : labelled) {
            legendEntry(c, lx, ly, l, f.colour());
            ly += 20;
        }
        if (f.colour() != null) {
            colourBar(c, f.colour(), px + pw + 12, py, ph);
        }
    }

    private static void grid(Canvas c, Mapping m) {
        double[] xs;
        String[] xl;
        if (!m.ax.categories().isEmpty()) {
            xs = new double[m.ax.categories().size()];
            for (int i = 0; i < xs.length; i++) {
                xs[i] = i + 1;
            }
            xl = m.ax.categories().toArray(new String[0]);
        } else {
            xs = Ticks.of(m.ax.min(), m.ax.max(), 6);
            xl = Ticks.labels(xs, Ticks.step(m.ax.min(), m.ax.max(), 6));
        }
        double[] ys = Ticks.of(m.ay.min(), m.ay.max(), 6);
        String[] yl = Ticks.labels(ys, Ticks.step(m.ay.min(), m.ay.max(), 6));
        for (int i = 0; i < xs.length; i++) {
            double x = m.x(xs[i]);
            c.polyline(new double[] {x, x}, new double[] {m.py, m.py + m.ph}, 2, GRID, 1f, false);
            c.polyline(new double[] {x, x}, new double[] {m.py + m.ph, m.py + m.ph + 5}, 2, FRAME, 1f, false);
            c.text(x, m.py + m.ph + 18, xl[i], FONT - 1, Canvas.Anchor.MIDDLE, false, false);
        }
        for (int i = 0; i < ys.length; i++) {
            double y = m.y(ys[i]);
            c.polyline(new double[] {m.px, m.px + m.pw}, new double[] {y, y}, 2, GRID, 1f, false);
            c.polyline(new double[] {m.px - 5, m.px}, new double[] {y, y}, 2, FRAME, 1f, false);
            c.text(m.px - 8, y + 4, yl[i], FONT - 1, Canvas.Anchor.END, false, false);
        }
    }

    private static void layer(Canvas c, Mapping m, Layer l, ColourScale scale) {
        if (l instanceof Layer.Line line) {
            double[][] p = m.points(line.x(), line.y());
            c.polyline(p[0], p[1], thin(p[0], p[1], p[0].length), line.rgb(), line.width(), line.dashed());
        } else if (l instanceof Layer.Gradient g) {
            gradient(c, m, g, scale);
        } else if (l instanceof Layer.Rule r) {
            c.polyline(new double[] {m.px, m.px + m.pw}, new double[] {m.y(r.y()), m.y(r.y())}, 2, r.rgb(), 1.6f,
                    r.dashed());
        } else if (l instanceof Layer.Area a) {
            int n = a.x().length;
            double[] xs = new double[2 * n];
            double[] ys = new double[2 * n];
            for (int i = 0; i < n; i++) {
                xs[i] = m.x(a.x()[i]);
                ys[i] = m.y(a.upper()[i]);
                xs[2 * n - 1 - i] = xs[i];
                ys[2 * n - 1 - i] = m.y(a.lower()[i]);
            }
            c.polygon(xs, ys, 2 * n, a.rgb(), 0.2);
        } else if (l instanceof Layer.Band b) {
            c.rect(m.px, m.y(b.upper()), m.pw, m.y(b.lower()) - m.y(b.upper()), b.rgb(), 0.18, -1);
        } else if (l instanceof Layer.Points p) {
            for (int i = 0; i < p.x().length; i++) {
                c.marker(m.x(p.x()[i]), m.y(p.y()[i]), 10, p.shape(), p.rgb());
            }
        } else if (l instanceof Layer.Bars b) {
            for (int i = 0; i < b.counts().length; i++) {
                double x0 = m.x(b.edges()[i]);
                double x1 = m.x(b.edges()[i + 1]);
                double y1 = m.y(b.counts()[i]);
                c.rect(x0, y1, x1 - x0, m.y(0) - y1, b.rgb(), 0.85, 0xffffff);
            }
        } else if (l instanceof Layer.Boxes bs) {
            for (int i = 0; i < bs.boxes().size(); i++) {
                box(c, m, bs.at()[i], bs.halfWidth(), bs.boxes().get(i));
            }
        }
    }

    private static void box(Canvas c, Mapping m, double at, double half, Layer.Box b) {
        double x0 = m.x(at - half);
        double x1 = m.x(at + half);
        double xm = m.x(at);
        double cap = 0.4 * half;
        c.polyline(new double[] {xm, xm}, new double[] {m.y(b.low()), m.y(b.q1())}, 2, FRAME, 1.2f, false);
        c.polyline(new double[] {xm, xm}, new double[] {m.y(b.q3()), m.y(b.high())}, 2, FRAME, 1.2f, false);
        c.polyline(new double[] {m.x(at - cap), m.x(at + cap)}, new double[] {m.y(b.low()), m.y(b.low())}, 2, FRAME,
                1.2f, false);
        c.polyline(new double[] {m.x(at - cap), m.x(at + cap)}, new double[] {m.y(b.high()), m.y(b.high())}, 2,
                FRAME, 1.2f, false);
        c.rect(x0, m.y(b.q3()), x1 - x0, Math.max(1, m.y(b.q1()) - m.y(b.q3())), b.rgb(), 0.6, FRAME);
        c.polyline(new double[] {x0, x1}, new double[] {m.y(b.median()), m.y(b.median())}, 2, 0x000000, 2f, false);
    }

    /**
     * The path is thinned first ({@link #thin}, each kept point keeping its own value), then runs
     * of consecutive points whose colours fall in the same of 64 levels become one polyline.
     */
    private static void gradient(Canvas c, Mapping m, Layer.Gradient g, ColourScale scale) {
        int all = g.x().length;
        double[] px = new double[all];
        double[] py = new double[all];
        double[] pv = g.value().clone();
        for (int i = 0; i < all; i++) {
            px[i] = m.x(g.x()[i]);
            py[i] = m.y(g.y()[i]);
        }
        int n = thin(px, py, pv, all);
        double[] xs = new double[n];
        double[] ys = new double[n];
        int i = 0;
        while (i < n - 1) {
            int level = level(scale, pv[i]);
            int j = i;
            int k = 0;
            xs[k] = px[i];
            ys[k++] = py[i];
            while (j < n - 1 && level(scale, pv[j]) == level) {
                j++;
                xs[k] = px[j];
                ys[k++] = py[j];
            }
            double mid = scale.min() + (level + 0.5) / COLOUR_LEVELS * (scale.max() - scale.min());
            c.polyline(xs, ys, k, scale.rgb(mid), 2f, false);
            i = j;
        }
    }

    /** @return {@link #thin(double[], double[], double[], int)} without values */
    static int thin(double[] x, double[] y, int n) {
        return thin(x, y, null, n);
    }

    /**
     * Drops, in place, every point closer than {@link #THIN_PX} in both directions to the last
     * point kept (the last point is always kept): a line of 20 000 points across 600 px draws the
     * same at a fraction of the cost, in PNG, SVG and PDF alike.
     *
     * @param v values carried along with the points (colours), or null
     * @return the number of points kept, at the front of the arrays
     */
    static int thin(double[] x, double[] y, double[] v, int n) {
        if (n < 3) {
            return n;
        }
        int k = 1;
        for (int i = 1; i < n; i++) {
            if (i == n - 1 || Math.abs(x[i] - x[k - 1]) >= THIN_PX || Math.abs(y[i] - y[k - 1]) >= THIN_PX) {
                x[k] = x[i];
                y[k] = y[i];
                if (v != null) {
                    v[k] = v[i];
                }
                k++;
            }
        }
        return k;
    }

    private static int level(ColourScale s, double v) {
        double f = s.max() > s.min() ? (v - s.min()) / (s.max() - s.min()) : 0;
        return (int) Math.max(0, Math.min(COLOUR_LEVELS - 1, Math.floor((f >= 0 ? f : 0) * COLOUR_LEVELS)));
    }

    private static void legendEntry(Canvas c, double x, double y, Layer l, ColourScale scale) {
        if (l instanceof Layer.Line line) {
            c.polyline(new double[] {x, x + 24}, new double[] {y, y}, 2, line.rgb(), 2f, line.dashed());
        } else if (l instanceof Layer.Rule r) {
            c.polyline(new double[] {x, x + 24}, new double[] {y, y}, 2, r.rgb(), 1.6f, r.dashed());
        } else if (l instanceof Layer.Gradient) {
            c.polyline(new double[] {x, x + 8}, new double[] {y, y}, 2, scale.rgb(scale.min()), 3f, false);
            c.polyline(new double[] {x + 8, x + 16}, new double[] {y, y}, 2,
                    scale.rgb(0.5 * (scale.min() + scale.max())), 3f, false);
            c.polyline(new double[] {x + 16, x + 24}, new double[] {y, y}, 2, scale.rgb(scale.max()), 3f, false);
        } else if (l instanceof Layer.Band b) {
            c.rect(x, y - 6, 24, 12, b.rgb(), 0.25, -1);
        } else if (l instanceof Layer.Area a) {
            c.rect(x, y - 6, 24, 12, a.rgb(), 0.25, -1);
        } else if (l instanceof Layer.Points p) {
            c.marker(x + 12, y, 9, p.shape(), p.rgb());
        } else if (l instanceof Layer.Bars b) {
            c.rect(x, y - 6, 24, 12, b.rgb(), 0.85, -1);
        } else if (l instanceof Layer.Boxes bs && !bs.boxes().isEmpty()) {
            c.rect(x, y - 6, 24, 12, bs.boxes().get(0).rgb(), 0.6, FRAME);
        } else {
            c.rect(x, y - 6, 24, 12, 0x9ecae1, 0.6, FRAME);
        }
        String text = l.label();
        if (text.length() > 32) {
            text = text.substring(0, 31) + "\u2026";
        }
        c.text(x + 30, y + 4, text, FONT - 1, Canvas.Anchor.START, false, false);
    }

    private static void colourBar(Canvas c, ColourScale s, double x, double y, double h) {
        int steps = 48;
        for (int i = 0; i < steps; i++) {
            double v = s.min() + (i + 0.5) / steps * (s.max() - s.min());
            c.rect(x, y + h - (i + 1) * h / steps, 14, h / steps + 0.5, s.rgb(v), 1, -1);
        }
        c.rect(x, y, 14, h, -1, 1, FRAME);
        double[] ticks = Ticks.of(s.min(), s.max(), 5);
        String[] labels = Ticks.labels(ticks, Ticks.step(s.min(), s.max(), 5));
        for (int i = 0; i < ticks.length; i++) {
            double ty = y + h - (ticks[i] - s.min()) / (s.max() - s.min()) * h;
            c.polyline(new double[] {x + 14, x + 18}, new double[] {ty, ty}, 2, FRAME, 1f, false);
            c.text(x + 20, ty + 4, labels[i], FONT - 2, Canvas.Anchor.START, false, false);
        }
        c.text(x + 66, y + h / 2, s.label(), FONT - 1, Canvas.Anchor.MIDDLE, true, false);
    }

    /** Data to pixel coordinates of the plot area. */
    private record Mapping(Axis ax, Axis ay, double px, double py, double pw, double ph) {
        double x(double v) {
            return px + (v - ax.min()) / (ax.max() - ax.min()) * pw;
        }

        double y(double v) {
            return py + ph - (v - ay.min()) / (ay.max() - ay.min()) * ph;
        }

        double[][] points(double[] xs, double[] ys) {
            double[] a = new double[xs.length];
            double[] b = new double[ys.length];
            int k = 0;
            for (int i = 0; i < xs.length; i++) {
                if (Double.isFinite(xs[i]) && Double.isFinite(ys[i])) {
                    a[k] = x(xs[i]);
                    b[k++] = y(ys[i]);
                }
            }
            return new double[][] {java.util.Arrays.copyOf(a, k), java.util.Arrays.copyOf(b, k)};
        }
    }
}
