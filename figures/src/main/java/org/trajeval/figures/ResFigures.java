package org.trajeval.figures;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.trajeval.core.report.ResultSet;

/**
 * The figures of {@code trajeval res}: per error kind, box plots of the saved results side by
 * side (one box per result, coloured by name, so the seeds of one method share a colour) and the
 * errors over time overlaid, and the relative errors per sub-trajectory length (boxes per length,
 * results side by side) when the results hold them. Rotations in degrees. Results saved without per-value errors (an
 * {@code eval --out} JSON) appear in the tables only.
 */
public final class ResFigures {
    static final int[] PALETTE = {0x1f77b4, 0xd62728, 0x2ca02c, 0xff7f0e, 0x9467bd, 0x8c564b, 0xe377c2, 0x7f7f7f};

    private ResFigures() {
    }

    /** @return the figures, kind by kind (box plot, then over time) */
    public static List<Figure> of(List<ResultSet> results) {
        Map<String, Integer> colour = new LinkedHashMap<>();
        for (ResultSet r : results) {
            colour.putIfAbsent(r.name(), PALETTE[colour.size() % PALETTE.length]);
        }
        List<Figure> out = new ArrayList<>();
        for (ResultSet.Kind k : ResultSet.Kind.values()) {
            double f = k.rotation() ? 180.0 / Math.PI : 1.0;
            String label = k.rotation() ? k.label().replace("(rad)", "(deg)") : k.label();
            String stem = k.key().replaceFirst("_(m|rad)$", "");
            List<String> names = new ArrayList<>();
            List<Layer.Box> boxes = new ArrayList<>();
            List<Layer> lines = new ArrayList<>();
            List<double[]> all = new ArrayList<>();
            String timeUnit = null;
            boolean mixedTime = false;
            for (ResultSet r : results) {
                ResultSet.Errors e = r.of(k);
                if (e == null || e.values() == null || e.values().length == 0) {
                    continue;
                }
                double[] v = scaled(e.values(), f);
                all.add(v);
                names.add(r.name() + " (" + r.origin() + ")");
                boxes.add(box(v, colour.get(r.name())));
                if (e.t() != null) {
                    double[][] d = Decimate.minMax(e.t(), v, Decimate.SERIES_BUCKETS);
                    lines.add(new Layer.Line(r.name(), d[0], d[1], colour.get(r.name()), 1.2f, false));
                    mixedTime |= timeUnit != null && !timeUnit.equals(r.timeUnit());
                    timeUnit = r.timeUnit();
                }
            }
            if (boxes.isEmpty()) {
                continue;
            }
            out.add(new Figure("res_" + stem + "_box", label.replaceFirst(" \\(.*", "") + " per result",
                    Axis.categorical("result", names), Axis.fromZero(label, all.toArray(new double[0][])),
                    List.of(new Layer.Boxes(null, boxes)), null, false));
            if (!lines.isEmpty() && !mixedTime) {
                double end = 0;
                for (Layer l : lines) {
                    double[] x = ((Layer.Line) l).x();
                    end = Math.max(end, x[x.length - 1]);
                }
                out.add(new Figure("res_" + stem + "_time", label.replaceFirst(" \\(.*", "") + " over time",
                        new Axis("s".equals(timeUnit) ? "time from start (s)" : "frame", 0, end > 0 ? end : 1,
                                List.of()), Axis.fromZero(label, all.toArray(new double[0][])), lines, null, false));
            }
        }
        List<SubTrajectoryFigures.Named> segments = new ArrayList<>();
        for (ResultSet r : results) {
            boolean first = segments.stream().noneMatch(n -> r.name().equals(n.name()));
            segments.add(new SubTrajectoryFigures.Named(first ? r.name() : null, colour.get(r.name()), r.segments()));
        }
        out.addAll(SubTrajectoryFigures.of(segments));
        return out;
    }

    /** Tukey box: quartiles by linear interpolation of the sorted values, whiskers within 1.5 IQR. */
    static Layer.Box box(double[] values, int rgb) {
        double[] v = Arrays.stream(values).filter(Double::isFinite).sorted().toArray();
        if (v.length == 0) {
            return new Layer.Box(0, 0, 0, 0, 0, 0, rgb);
        }
        double q1 = quantile(v, 0.25);
        double q3 = quantile(v, 0.75);
        double lowFence = q1 - 1.5 * (q3 - q1);
        double highFence = q3 + 1.5 * (q3 - q1);
        double low = v[0];
        for (double d : v) {
            if (d >= lowFence) {
                low = d;
                break;
            }
        }
        double high = v[v.length - 1];
        for (int i = v.length - 1; i >= 0; i--) {
            if (v[i] <= highFence) {
                high = v[i];
                break;
            }
        }
        return new Layer.Box(low, q1, quantile(v, 0.5), q3, high, v.length, rgb);
    }

    /** numpy's default (linear) quantile of sorted values. */
    static double quantile(double[] sorted, double p) {
        double h = (sorted.length - 1) * p;
        int i = (int) Math.floor(h);
        return i + 1 < sorted.length ? sorted[i] + (h - i) * (sorted[i + 1] - sorted[i]) : sorted[i];
    }

    private static double[] scaled(double[] v, double f) {
        double[] out = new double[v.length];
        for (int i = 0; i < v.length; i++) {
            out[i] = v[i] * f;
        }
        return out;
    }
}
