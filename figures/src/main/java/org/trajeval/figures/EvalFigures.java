package org.trajeval.figures;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.EvaluationSeries;
import org.trajeval.core.report.SavedEvaluation;

/**
 * The figures of one evaluation ({@code trajeval eval --plot}), built from the report and its
 * series alone, so they can be redrawn from a saved folder without rescoring:
 * trajectories (estimate coloured by ATE), ATE and RPE translation and rotation over time with
 * mean, median, RMSE and a mean +- std band, a histogram of each error, KITTI drift per
 * segment length when drift was computed, and box plots of the relative error per sub-trajectory
 * length when the series hold segments. Rotations are drawn in degrees, as readers expect.
 */
public final class EvalFigures {
    static final int REFERENCE = 0x444444;
    static final int ERROR = 0x1f77b4;
    static final int MEAN = 0xd62728;
    static final int MEDIAN = 0x2ca02c;
    static final int RMSE = 0xff7f0e;
    private static final double DEG = 180.0 / Math.PI;

    private EvalFigures() {
    }

    /** @return every figure of the evaluation, in page order */
    public static List<Figure> of(SavedEvaluation saved, PlotPlane plane) {
        EvaluationReport r = saved.report();
        EvaluationSeries s = saved.series();
        List<Figure> out = new ArrayList<>();
        out.add(trajectories(r, s, plane));
        String time = "s".equals(s.timeUnit()) ? "time from start (s)" : "frame";
        EvaluationSeries.Poses p = s.poses();
        EvaluationSeries.Pairs q = s.pairs();
        out.add(overTime("ate_trans", "ATE translation over time", time, p.t(), p.ateTransM(), 1.0,
                "ATE translation (m)", r.ate().transM()));
        out.add(overTime("ate_rot", "ATE rotation over time", time, p.t(), p.ateRotRad(), DEG,
                "ATE rotation (deg)", r.ate().rotRad()));
        String rpe = " (" + rpeHorizon(r.rpe()) + ")";
        out.add(overTime("rpe_trans", "RPE translation over time" + rpe, time, q.t(), q.rpeTransM(), 1.0,
                "RPE translation (m)", r.rpe().transM()));
        out.add(overTime("rpe_rot", "RPE rotation over time" + rpe, time, q.t(), q.rpeRotRad(), DEG,
                "RPE rotation (deg)", r.rpe().rotRad()));
        out.add(histogram("hist_ate_trans", "ATE translation (m)", p.ateTransM(), 1.0, "poses"));
        out.add(histogram("hist_ate_rot", "ATE rotation (deg)", p.ateRotRad(), DEG, "poses"));
        out.add(histogram("hist_rpe_trans", "RPE translation (m)", q.rpeTransM(), 1.0, "pairs"));
        out.add(histogram("hist_rpe_rot", "RPE rotation (deg)", q.rpeRotRad(), DEG, "pairs"));
        if (r.drift() != null && !r.drift().perLength().isEmpty()) {
            out.addAll(drift(r.drift()));
        }
        out.addAll(SubTrajectoryFigures.of(List.of(new SubTrajectoryFigures.Named(null, ERROR, s.segments()))));
        return out;
    }

    /** What alignment was applied, for titles: "not aligned" or "aligned: SE(3) (Umeyama)". */
    static String alignment(EvaluationReport r) {
        String m = r.alignment() == null ? "none" : r.alignment().model();
        String scale = m.startsWith("sim") ? ", scale " + fmt(r.alignment().scale()) : "";
        return alignment(m) + scale;
    }

    /** @return the phrase for an alignment model name as the report writes it */
    static String alignment(String model) {
        return switch (model) {
            case "none" -> "not aligned";
            case "se2" -> "aligned: SE(2)";
            case "sim2" -> "aligned: Sim(2)";
            case "se3" -> "aligned: SE(3) (Umeyama)";
            case "sim3" -> "aligned: Sim(3) (Umeyama)";
            case "origin" -> "aligned at the first pose";
            case "posyaw" -> "aligned: position and yaw";
            default -> "aligned: " + model;
        };
    }

    static Figure trajectories(EvaluationReport r, EvaluationSeries s, PlotPlane plane) {
        EvaluationSeries.Poses p = s.poses();
        double[][] ref = {p.refX(), p.refY(), p.refZ()};
        double[][] est = {p.estX(), p.estY(), p.estZ()};
        PlotPlane pl = plane.resolve(p.refX(), p.refY(), p.refZ());
        int h = pl.horizontal();
        int v = pl.vertical();
        int[] idx = Decimate.stride(p.size(), Decimate.PATH_POINTS);
        double[] rx = Decimate.pick(ref[h], idx);
        double[] ry = Decimate.pick(ref[v], idx);
        double[] ex = Decimate.pick(est[h], idx);
        double[] ey = Decimate.pick(est[v], idx);
        double[] err = Decimate.pick(p.ateTransM(), idx);
        Axis ax = Axis.spanning(PlotPlane.name(h) + " (m)", rx, ex);
        Axis ay = Axis.spanning(PlotPlane.name(v) + " (m)", ry, ey);
        double maxErr = Axis.fromZero("", p.ateTransM()).max() / 1.05;
        List<Layer> layers = new ArrayList<>();
        layers.add(new Layer.Line("reference", rx, ry, REFERENCE, 1.5f, true));
        layers.add(new Layer.Gradient("estimate, coloured by ATE", ex, ey, err));
        if (ex.length > 0) {
            layers.add(new Layer.Points("start", new double[] {ex[0]}, new double[] {ey[0]}, 0xffffff,
                    Layer.Shape.CIRCLE));
            layers.add(new Layer.Points("end", new double[] {ex[ex.length - 1]}, new double[] {ey[ey.length - 1]},
                    0xffffff, Layer.Shape.SQUARE));
        }
        String plName = PlotPlane.name(h) + "-" + PlotPlane.name(v);
        return new Figure("trajectories", "Trajectories in " + plName + ", " + alignment(r), ax, ay, layers,
                new ColourScale("ATE translation (m)", 0, maxErr > 0 ? maxErr : 1.0), true);
    }

    static Figure overTime(String name, String title, String timeLabel, double[] t, double[] values, double factor,
            String valueLabel, EvaluationReport.Stats stats) {
        double[] y = scaled(values, factor);
        double[][] d = Decimate.minMax(t, y, Decimate.SERIES_BUCKETS);
        List<Layer> layers = new ArrayList<>();
        if (stats.mean() != null && stats.std() != null) {
            layers.add(new Layer.Band("mean \u00b1 std", Math.max(0, factor * (stats.mean() - stats.std())),
                    factor * (stats.mean() + stats.std()), MEAN));
        }
        layers.add(new Layer.Line(valueLabel.replaceFirst(" \\(.*", ""), d[0], d[1], ERROR, 1.2f, false));
        if (stats.mean() != null) {
            layers.add(new Layer.Rule("mean " + fmt(factor * stats.mean()), factor * stats.mean(), MEAN, false));
            layers.add(new Layer.Rule("median " + fmt(factor * stats.median()), factor * stats.median(), MEDIAN,
                    true));
            layers.add(new Layer.Rule("RMSE " + fmt(factor * stats.rmse()), factor * stats.rmse(), RMSE, true));
        }
        // relative time from the first pose: the axis runs from 0 to the last stamp, unpadded
        double end = t.length > 0 && t[t.length - 1] > 0 ? t[t.length - 1] : 1.0;
        return new Figure(name, title, new Axis(timeLabel, 0, end, List.of()), Axis.fromZero(valueLabel, y),
                layers, null, false);
    }

    static Figure histogram(String name, String valueLabel, double[] values, double factor, String what) {
        double[] v = scaled(values, factor);
        double hi = 0;
        int n = 0;
        for (double d : v) {
            if (Double.isFinite(d)) {
                hi = Math.max(hi, d);
                n++;
            }
        }
        int bins = Math.max(10, Math.min(60, (int) Math.ceil(Math.sqrt(n))));
        double width = hi > 0 ? hi / bins : 1.0 / bins;
        double[] edges = new double[bins + 1];
        for (int i = 0; i <= bins; i++) {
            edges[i] = i * width;
        }
        double[] counts = new double[bins];
        for (double d : v) {
            if (Double.isFinite(d)) {
                counts[Math.min(bins - 1, (int) (d / width))]++;
            }
        }
        return new Figure(name, "Histogram of " + valueLabel.replaceFirst(" \\(.*", "") + " (" + n + " " + what + ")",
                new Axis(valueLabel, 0, edges[bins], List.of()), Axis.fromZero(what + " per bin", counts),
                List.of(new Layer.Bars(null, edges, counts, ERROR)), null, false);
    }

    static List<Figure> drift(EvaluationReport.Drift d) {
        int n = d.perLength().size();
        double[] len = new double[n];
        double[] trans = new double[n];
        double[] rot = new double[n];
        for (int i = 0; i < n; i++) {
            EvaluationReport.DriftAtLength a = d.perLength().get(i);
            len[i] = a.lengthM();
            trans[i] = a.transPct() == null ? Double.NaN : a.transPct();
            rot[i] = a.rotDegPerM() == null ? Double.NaN : 100.0 * a.rotDegPerM();
        }
        Axis ax = new Axis("segment length (m)", 0, Axis.fromZero("", len).max(), List.of());
        return List.of(
                new Figure("drift_trans", "Translational drift per segment length (KITTI devkit)", ax,
                        Axis.fromZero("translation error (%)", trans), List.of(
                                new Layer.Line(null, len, trans, ERROR, 1.6f, false),
                                new Layer.Points(null, len, trans, ERROR, Layer.Shape.CIRCLE)), null, false),
                new Figure("drift_rot", "Rotational drift per segment length (KITTI devkit)", ax,
                        Axis.fromZero("rotation error (deg/100 m)", rot), List.of(
                                new Layer.Line(null, len, rot, ERROR, 1.6f, false),
                                new Layer.Points(null, len, rot, ERROR, Layer.Shape.CIRCLE)), null, false));
    }

    static String rpeHorizon(EvaluationReport.Rpe rpe) {
        String unit = switch (rpe.unit()) {
            case "s" -> " s";
            case "m" -> " m";
            default -> rpe.delta() == 1 ? " frame" : " frames";
        };
        return "delta " + fmt(rpe.delta()) + unit + ", " + rpe.pairSelection().replace('_', ' ');
    }

    private static double[] scaled(double[] v, double factor) {
        if (factor == 1.0) {
            return v;
        }
        double[] out = new double[v.length];
        for (int i = 0; i < v.length; i++) {
            out[i] = v[i] * factor;
        }
        return out;
    }

    static String fmt(double v) {
        double a = Math.abs(v);
        if (a != 0 && (a < 1e-3 || a >= 1e5)) {
            return String.format(Locale.ROOT, "%.3g", v);
        }
        String t = String.format(Locale.ROOT, "%.4g", v);
        return t.contains(".") ? t.replaceFirst("0+$", "").replaceFirst("\\.$", "") : t;
    }
}
