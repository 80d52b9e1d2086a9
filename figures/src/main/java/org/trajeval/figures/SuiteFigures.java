package org.trajeval.figures;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.trajeval.core.protocol.RunMetric;
import org.trajeval.core.report.SequencePlot;
import org.trajeval.core.report.SuiteReport;

/**
 * The suite report's figures as data: box plots per method of every error (ATE and RPE,
 * translation and rotation, and the score's metrics) with human labels and axes from zero; per
 * sequence the trajectories in the plane that shows them (every seed drawn, the median seed
 * bold; one run alone is coloured by its error), and the position error over relative time
 * (per method the median over seeds with the min-max envelope). Titles say the alignment the
 * evaluations actually applied.
 */
public final class SuiteFigures {
    /** Errors always drawn, besides the score's own metrics. */
    static final List<RunMetric> ERRORS = List.of(RunMetric.ATE_TRANS_RMSE_M, RunMetric.ATE_ROT_RMSE_RAD,
            RunMetric.RPE_TRANS_RMSE_M, RunMetric.RPE_ROT_RMSE_RAD);
    /** Time bins of the error-over-time envelope. */
    static final int TIME_BINS = 200;

    private SuiteFigures() {
    }

    /** @return one box-plot figure per metric that has values */
    public static List<Figure> boxes(SuiteReport r) {
        Set<String> keys = new LinkedHashSet<>();
        ERRORS.forEach(m -> keys.add(m.key()));
        r.protocol().score().forEach(t -> keys.add(t.metric()));
        List<String> methods = r.methods().stream().map(SuiteReport.MethodSummary::name).toList();
        List<Figure> out = new ArrayList<>();
        for (String k : keys) {
            MetricLabel label = MetricLabel.of(k);
            RunMetric rm = RunMetric.fromKey(k);
            List<Layer.Box> boxes = new ArrayList<>();
            List<double[]> all = new ArrayList<>();
            int runs = 0;
            for (int i = 0; i < methods.size(); i++) {
                String m = methods.get(i);
                double[] v = r.runs().stream().filter(x -> x.method().equals(m) && x.ok())
                        .mapToDouble(x -> value(x, k, rm) * label.factor()).filter(Double::isFinite).toArray();
                all.add(v);
                runs += v.length;
                boxes.add(ResFigures.box(v, ResFigures.PALETTE[i % ResFigures.PALETTE.length]));
            }
            if (runs == 0) {
                continue;
            }
            out.add(new Figure("box_" + k, label.label() + " per method (" + runs + " successful runs)",
                    Axis.categorical("method", methods), Axis.fromZero(label.label(), all.toArray(new double[0][])),
                    List.of(new Layer.Boxes(null, boxes)), null, false));
        }
        return out;
    }

    private static double value(SuiteReport.RunEntry run, String key, RunMetric rm) {
        Double v = run.metrics() == null ? null : run.metrics().get(key);
        if (v != null) {
            return v;
        }
        return rm != null && run.evaluation() != null ? rm.of(run.evaluation()) : Double.NaN;
    }

    /** Trajectories of one sequence: reference dashed; per method every seed thin, the median seed bold. */
    public static Figure overlay(SequencePlot p, PlotPlane plane) {
        double[][] ref = {p.referenceX(), p.referenceY(), p.referenceZ()};
        PlotPlane pl = plane.resolve(p.referenceX(), p.referenceY(), p.referenceZ());
        int h = pl.horizontal();
        int v = pl.vertical();
        List<Layer> layers = new ArrayList<>();
        List<double[]> xs = new ArrayList<>(List.of(ref[h]));
        List<double[]> ys = new ArrayList<>(List.of(ref[v]));
        layers.add(new Layer.Line("reference", ref[h], ref[v], EvalFigures.REFERENCE, 1.5f, true));
        ColourScale scale = null;
        Map<String, List<SequencePlot.Trace>> byMethod = byMethod(p);
        int k = 0;
        for (Map.Entry<String, List<SequencePlot.Trace>> e : byMethod.entrySet()) {
            int rgb = ResFigures.PALETTE[k++ % ResFigures.PALETTE.length];
            List<SequencePlot.Trace> seeds = e.getValue();
            SequencePlot.Trace median = medianSeed(seeds);
            for (SequencePlot.Trace t : seeds) {
                double[][] c = {t.x(), t.y(), t.z()};
                xs.add(c[h]);
                ys.add(c[v]);
                if (p.estimates().size() == 1) {
                    double max = Axis.fromZero("", t.errorM()).max() / 1.05;
                    scale = new ColourScale("position error (m)", 0, max > 0 ? max : 1.0);
                    layers.add(new Layer.Gradient(t.method() + " (seed " + t.seed() + "), coloured by error", c[h],
                            c[v], t.errorM()));
                } else if (t != median) {
                    layers.add(new Layer.Line(null, c[h], c[v], rgb, 0.6f, false));
                }
            }
            if (p.estimates().size() > 1) {
                double[][] c = {median.x(), median.y(), median.z()};
                layers.add(new Layer.Line(e.getKey() + (seeds.size() > 1 ? " (median of " + seeds.size()
                        + " seeds)" : " (seed " + median.seed() + ")"), c[h], c[v], rgb, 1.8f, false));
            }
        }
        String plName = PlotPlane.name(h) + "-" + PlotPlane.name(v);
        return new Figure("trajectories_" + safe(p.sequence()), "Trajectories, " + p.sequence() + ", in " + plName
                + ", " + alignments(p), Axis.spanning(PlotPlane.name(h) + " (m)", xs.toArray(new double[0][])),
                Axis.spanning(PlotPlane.name(v) + " (m)", ys.toArray(new double[0][])), layers, scale, true);
    }

    /** Position error over relative time: per method the median over seeds and the min-max envelope. */
    public static Figure errorOverTime(SequencePlot p) {
        double end = 0;
        for (SequencePlot.Trace t : p.estimates()) {
            for (int i = 0; i < t.t().length; i++) {
                if (Double.isFinite(t.errorM()[i])) {
                    end = Math.max(end, t.t()[i]);
                }
            }
        }
        double width = (end > 0 ? end : 1.0) / TIME_BINS;
        List<Layer> layers = new ArrayList<>();
        List<double[]> all = new ArrayList<>();
        int k = 0;
        for (Map.Entry<String, List<SequencePlot.Trace>> e : byMethod(p).entrySet()) {
            int rgb = ResFigures.PALETTE[k++ % ResFigures.PALETTE.length];
            List<SequencePlot.Trace> seeds = e.getValue();
            double[][] binned = new double[seeds.size()][];
            for (int s = 0; s < seeds.size(); s++) {
                binned[s] = binMeans(seeds.get(s), width);
            }
            List<Double> x = new ArrayList<>();
            List<double[]> spread = new ArrayList<>();
            for (int b = 0; b < TIME_BINS; b++) {
                int bin = b;
                double[] v = Arrays.stream(binned).mapToDouble(a -> a[bin]).filter(Double::isFinite).sorted()
                        .toArray();
                if (v.length > 0) {
                    x.add((b + 0.5) * width);
                    spread.add(new double[] {v[0], ResFigures.quantile(v, 0.5), v[v.length - 1]});
                }
            }
            double[] xs = x.stream().mapToDouble(Double::doubleValue).toArray();
            double[] lo = spread.stream().mapToDouble(a -> a[0]).toArray();
            double[] med = spread.stream().mapToDouble(a -> a[1]).toArray();
            double[] hi = spread.stream().mapToDouble(a -> a[2]).toArray();
            all.add(hi);
            if (seeds.size() > 1) {
                layers.add(new Layer.Area(null, xs, lo, hi, rgb));
            }
            layers.add(new Layer.Line(e.getKey() + (seeds.size() > 1 ? " (median, " + seeds.size() + " seeds)" : ""),
                    xs, med, rgb, 1.4f, false));
        }
        String time = "s".equals(p.timeUnit()) ? "time from start (s)" : "frame";
        return new Figure("error_" + safe(p.sequence()), "Position error over time, " + p.sequence() + ", "
                + alignments(p), new Axis(time, 0, end > 0 ? end : 1.0, List.of()),
                Axis.fromZero("position error (m)", all.toArray(new double[0][])), layers, null, false);
    }

    private static double[] binMeans(SequencePlot.Trace t, double width) {
        double[] sum = new double[TIME_BINS];
        int[] n = new int[TIME_BINS];
        for (int i = 0; i < t.t().length; i++) {
            double e = t.errorM()[i];
            if (Double.isFinite(e) && t.t()[i] >= 0) {
                int b = Math.min(TIME_BINS - 1, (int) (t.t()[i] / width));
                sum[b] += e;
                n[b]++;
            }
        }
        double[] out = new double[TIME_BINS];
        for (int b = 0; b < TIME_BINS; b++) {
            out[b] = n[b] == 0 ? Double.NaN : sum[b] / n[b];
        }
        return out;
    }

    private static Map<String, List<SequencePlot.Trace>> byMethod(SequencePlot p) {
        Map<String, List<SequencePlot.Trace>> m = new LinkedHashMap<>();
        for (SequencePlot.Trace t : p.estimates()) {
            m.computeIfAbsent(t.method(), x -> new ArrayList<>()).add(t);
        }
        return m;
    }

    /** The seed whose RMS position error is the (lower) median among the method's seeds. */
    static SequencePlot.Trace medianSeed(List<SequencePlot.Trace> seeds) {
        List<SequencePlot.Trace> sorted = new ArrayList<>(seeds);
        sorted.sort((a, b) -> Double.compare(rms(a.errorM()), rms(b.errorM())));
        return sorted.get((sorted.size() - 1) / 2);
    }

    private static double rms(double[] v) {
        double s = 0;
        int n = 0;
        for (double d : v) {
            if (Double.isFinite(d)) {
                s += d * d;
                n++;
            }
        }
        return n == 0 ? Double.POSITIVE_INFINITY : Math.sqrt(s / n);
    }

    /** The alignment phrase when every run used the same model, else the models listed. */
    static String alignments(SequencePlot p) {
        Set<String> models = new LinkedHashSet<>();
        p.estimates().forEach(t -> models.add(t.alignment()));
        if (models.isEmpty()) {
            return "no scored run";
        }
        if (models.size() == 1) {
            return EvalFigures.alignment(models.iterator().next());
        }
        return "aligned per run: " + String.join(", ", models);
    }

    private static String safe(String id) {
        String s = id.toLowerCase(java.util.Locale.ROOT).replaceAll("[^a-z0-9_\\-]+", "-");
        return s.isEmpty() ? "sequence" : s;
    }
}
