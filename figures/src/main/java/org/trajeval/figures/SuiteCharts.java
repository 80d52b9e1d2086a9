package org.trajeval.figures;

import java.awt.Color;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.BoxChart;
import org.knowm.xchart.BoxChartBuilder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.internal.chartpart.IChart;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.trajeval.core.report.SequencePlot;

/** Draws the report's charts as PNG data URIs (XChart stays in this package). */
final class SuiteCharts {
    private static final Color[] PALETTE = {new Color(0x1f77b4), new Color(0xd62728), new Color(0x2ca02c),
        new Color(0xff7f0e), new Color(0x9467bd), new Color(0x8c564b), new Color(0xe377c2), new Color(0x7f7f7f)};
    private static final Color REFERENCE = new Color(0x222222);

    private SuiteCharts() {
    }

    /** Reference path and aligned estimates in the plane, equal axis scales. */
    static String overlay(SequencePlot p) {
        XYChart c = new XYChartBuilder().width(560).height(420).title("Trajectories, " + p.sequence() + " (aligned)")
                .xAxisTitle("x (m)").yAxisTitle("y (m)").build();
        style(c);
        XYSeries ref = c.addSeries("reference", p.referenceX(), p.referenceY());
        ref.setMarker(SeriesMarkers.NONE);
        ref.setLineColor(REFERENCE);
        ref.setLineWidth(2.5f);
        double minX = min(p.referenceX());
        double maxX = max(p.referenceX());
        double minY = min(p.referenceY());
        double maxY = max(p.referenceY());
        int k = 0;
        for (SequencePlot.Trace t : p.estimates()) {
            XYSeries s = c.addSeries(t.method() + " (seed " + t.seed() + ")", t.x(), t.y());
            s.setMarker(SeriesMarkers.NONE);
            s.setLineColor(PALETTE[k++ % PALETTE.length]);
            s.setLineWidth(1.2f);
            minX = Math.min(minX, min(t.x()));
            maxX = Math.max(maxX, max(t.x()));
            minY = Math.min(minY, min(t.y()));
            maxY = Math.max(maxY, max(t.y()));
        }
        // equal scales: widen the shorter axis range (plot area is about 4:3)
        double w = maxX - minX;
        double h = maxY - minY;
        double span = Math.max(w, h * 4.0 / 3.0) * 1.05 + 1e-9;
        double cx = 0.5 * (minX + maxX);
        double cy = 0.5 * (minY + maxY);
        c.getStyler().setXAxisMin(cx - span / 2).setXAxisMax(cx + span / 2);
        c.getStyler().setYAxisMin(cy - span * 3.0 / 8.0).setYAxisMax(cy + span * 3.0 / 8.0);
        return png(c);
    }

    /** Position error over time of each method's plotted run. */
    static String errorOverTime(SequencePlot p) {
        XYChart c = new XYChartBuilder().width(560).height(420).title("Position error, " + p.sequence())
                .xAxisTitle("time (s)").yAxisTitle("|p_est - p_ref| (m)").build();
        style(c);
        c.getStyler().setXAxisDecimalPattern("0.#");
        int k = 0;
        boolean any = false;
        for (SequencePlot.Trace t : p.estimates()) {
            List<Double> xs = new ArrayList<>();
            List<Double> ys = new ArrayList<>();
            for (int i = 0; i < t.t().length; i++) {
                if (Double.isFinite(t.errorM()[i])) {
                    xs.add(t.t()[i]);
                    ys.add(t.errorM()[i]);
                }
            }
            Color col = PALETTE[k++ % PALETTE.length];
            if (xs.isEmpty()) {
                continue;
            }
            XYSeries s = c.addSeries(t.method() + " (seed " + t.seed() + ")", xs, ys);
            s.setMarker(SeriesMarkers.NONE);
            s.setLineColor(col);
            s.setLineWidth(1.2f);
            any = true;
        }
        if (!any) {
            c.addSeries("no scored run", new double[] {0, 1}, new double[] {0, 0}).setMarker(SeriesMarkers.NONE);
        }
        return png(c);
    }

    /** One box per method of a metric's values over the successful runs. */
    static String boxes(String title, String yTitle, List<String> methods, List<double[]> values) {
        BoxChart c = new BoxChartBuilder().width(560).height(380).title(title).yAxisTitle(yTitle).build();
        c.getStyler().setChartBackgroundColor(Color.WHITE);
        c.getStyler().setLegendVisible(false);
        c.getStyler().setAntiAlias(true);
        boolean any = false;
        for (int i = 0; i < methods.size(); i++) {
            if (values.get(i).length > 0) {
                c.addSeries(methods.get(i), values.get(i));
                any = true;
            }
        }
        if (!any) {
            c.addSeries("no data", new double[] {0});
        }
        return png(c);
    }

    private static void style(XYChart c) {
        c.getStyler().setChartBackgroundColor(Color.WHITE);
        c.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        c.getStyler().setAntiAlias(true);
        c.getStyler().setPlotGridLinesVisible(true);
    }

    private static String png(IChart chart) {
        try {
            byte[] bytes = BitmapEncoder.getBitmapBytes(chart, BitmapEncoder.BitmapFormat.PNG);
            return "data:image/png;base64," + Base64.getEncoder().encodeToString(bytes);
        } catch (IOException e) {
            throw new UncheckedIOException("chart could not be encoded", e);
        }
    }

    private static double min(double[] v) {
        double m = Double.POSITIVE_INFINITY;
        for (double d : v) {
            m = Math.min(m, d);
        }
        return m;
    }

    private static double max(double[] v) {
        double m = Double.NEGATIVE_INFINITY;
        for (double d : v) {
            m = Math.max(m, d);
        }
        return m;
    }
}
