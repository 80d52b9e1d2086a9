package org.trajeval.figures;

import java.util.ArrayList;
import java.util.List;
import org.trajeval.core.report.FactorSweep;
import org.trajeval.core.report.SuiteReport;

/**
 * The stress sweeps' figures as data: per factor, each method's median of the first score metric
 * against the factor's level, with the shaded order-statistic interval of the median, and each
 * method's failure rate against the level with the breakdown rate as a dashed rule.
 */
public final class SweepFigures {
    private SweepFigures() {
    }

    /** @return two figures per factor: the metric's median, then the failure rate, against the level */
    public static List<Figure> of(SuiteReport r) {
        List<Figure> out = new ArrayList<>();
        if (r.factorSweeps() == null) {
            return out;
        }
        for (FactorSweep s : r.factorSweeps()) {
            double[] x = s.levels().stream().mapToDouble(Double::doubleValue).toArray();
            if (x.length == 0 || s.methods().isEmpty() || s.methods().get(0).levels().get(0).metrics().isEmpty()) {
                continue;
            }
            String metric = s.methods().get(0).levels().get(0).metrics().get(0).metric();
            MetricLabel label = MetricLabel.of(metric);
            List<Layer> values = new ArrayList<>();
            List<Layer> rates = new ArrayList<>();
            List<double[]> ys = new ArrayList<>();
            int k = 0;
            for (FactorSweep.MethodSweep m : s.methods()) {
                int rgb = ResFigures.PALETTE[k++ % ResFigures.PALETTE.length];
                List<double[]> pts = new ArrayList<>();
                double[] rate = new double[x.length];
                for (int i = 0; i < m.levels().size(); i++) {
                    FactorSweep.Level l = m.levels().get(i);
                    FactorSweep.LevelMetric lm = l.metrics().get(0);
                    rate[i] = l.failureRate() == null ? Double.NaN : l.failureRate().estimate();
                    if (lm.median() != null) {
                        double f = label.factor();
                        pts.add(new double[] {l.level(), lm.median() * f, lm.lower() * f, lm.upper() * f});
                    }
                }
                if (!pts.isEmpty()) {
                    double[] px = pts.stream().mapToDouble(p -> p[0]).toArray();
                    double[] med = pts.stream().mapToDouble(p -> p[1]).toArray();
                    double[] lo = pts.stream().mapToDouble(p -> p[2]).toArray();
                    double[] hi = pts.stream().mapToDouble(p -> p[3]).toArray();
                    values.add(new Layer.Area(null, px, lo, hi, rgb));
                    values.add(new Layer.Line(m.method() + (m.breakdownLevel() == null ? ""
                            : " (breaks down at " + SuiteHtml.fmt(m.breakdownLevel()) + ")"), px, med, rgb, 1.8f,
                            false));
                    values.add(new Layer.Points(null, px, med, rgb, Layer.Shape.CIRCLE));
                    ys.add(hi);
                }
                rates.add(new Layer.Line(m.method(), x, rate, rgb, 1.8f, false));
                rates.add(new Layer.Points(null, x, rate, rgb, Layer.Shape.SQUARE));
            }
            rates.add(new Layer.Rule("breakdown rate " + SuiteHtml.fmt(s.breakdownRate()), s.breakdownRate(),
                    0x888888, true));
            Axis levelAxis = Axis.spanning(s.factor() + " (level)", x);
            if (!ys.isEmpty()) {
                out.add(new Figure("sweep_" + safe(s.factor()), label.label() + " against " + s.factor()
                        + ": median and its interval over sequences and seeds", levelAxis,
                        Axis.fromZero(label.label(), ys.toArray(new double[0][])), values, null, false));
            }
            out.add(new Figure("sweep_" + safe(s.factor()) + "_failures", "Failure rate against " + s.factor(),
                    levelAxis, Axis.fromZero("failure rate", new double[] {1.0}), rates, null, false));
        }
        return out;
    }

    private static String safe(String s) {
        return s.toLowerCase(java.util.Locale.ROOT).replaceAll("[^a-z0-9_-]", "_");
    }
}
