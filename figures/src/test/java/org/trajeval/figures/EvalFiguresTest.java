package org.trajeval.figures;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.stream.Collectors;
import org.junit.jupiter.api.Test;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.EvaluationSeries;
import org.trajeval.core.report.SavedEvaluation;

/** The figures of one evaluation, checked on their data (axes, points, labels), not on pixels. */
class EvalFiguresTest {
    private static final double TOL = 1e-12;

    /** A drive along x and z (KITTI's camera frame: y is height, almost constant). */
    static SavedEvaluation kittiLikeDrive(int n, String alignment, boolean drift) {
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] z = new double[n];
        double[] ex = new double[n];
        double[] ate = new double[n];
        double[] rot = new double[n];
        for (int k = 0; k < n; k++) {
            t[k] = k;
            x[k] = 100 * Math.cos(2 * Math.PI * k / n);
            z[k] = 60 * Math.sin(2 * Math.PI * k / n);
            y[k] = 0.01 * Math.sin(k);
            ate[k] = 0.5 + 0.5 * Math.sin(k / 10.0);
            ex[k] = x[k] + ate[k];
            rot[k] = 0.01;
        }
        int m = n - 1;
        double[] pt = new double[m];
        double[] ph = new double[m];
        double[] rt = new double[m];
        double[] rr = new double[m];
        for (int k = 0; k < m; k++) {
            pt[k] = k;
            ph[k] = 1;
            rt[k] = 0.1;
            rr[k] = Math.toRadians(0.5);
        }
        EvaluationReport.Stats ateStats = new EvaluationReport.Stats(0.8, 0.5, 0.5, 0.35, 0.0, 1.0, 1.0, n);
        EvaluationReport.Stats small = new EvaluationReport.Stats(0.1, 0.1, 0.1, 0.0, 0.1, 0.1, 1.0, m);
        EvaluationReport r = new EvaluationReport(EvaluationReport.SCHEMA, EvaluationReport.SCHEMA_VERSION, "test",
                "kitti", new EvaluationReport.Inputs(
                        new EvaluationReport.InputInfo("gt.txt", "kitti", "given", n, null),
                        new EvaluationReport.InputInfo("est.txt", "kitti", "given", n, null)),
                new EvaluationReport.AssociationInfo("index", n, 0, 0, 0.0, 0.0, "crop", 1.0, null, null, null, 0,
                        List.of(), null),
                new EvaluationReport.AlignmentInfo(alignment, new double[][] {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                        new double[] {0, 0, 0}, 1.0, n),
                new EvaluationReport.Ate(ateStats, small),
                new EvaluationReport.Rpe(small, small, m, 1, "frames", "consecutive", "estimate", 1.0, 1.0),
                drift ? new EvaluationReport.Drift(1.0, 0.01, 10, 10, List.of(
                        new EvaluationReport.DriftAtLength(100, 2.0, 0.02, 5),
                        new EvaluationReport.DriftAtLength(200, 1.0, 0.01, 5)), 1000.0) : null,
                null, List.of(), null, null);
        return new SavedEvaluation(r, new EvaluationSeries("frame",
                new EvaluationSeries.Poses(t, x, y, z, ex, y, z, ate, rot),
                new EvaluationSeries.Pairs(pt, ph, rt, rr)));
    }

    private static Map<String, Figure> byName(List<Figure> figures) {
        return figures.stream().collect(Collectors.toMap(Figure::name, Function.identity()));
    }

    @Test
    void autoPlaneDrawsAKittiDriveInXz() {
        Figure f = byName(EvalFigures.of(kittiLikeDrive(500, "se3", false), PlotPlane.AUTO)).get("trajectories");
        assertEquals("x (m)", f.x().label());
        assertEquals("z (m)", f.y().label());
        assertTrue(f.equalScales());
        assertTrue(f.title().contains("x-z"), f.title());
    }

    @Test
    void givenPlaneIsUsedEvenWhenAutoWouldPickAnother() {
        Figure f = byName(EvalFigures.of(kittiLikeDrive(500, "se3", false), PlotPlane.XY)).get("trajectories");
        assertEquals("y (m)", f.y().label());
    }

    @Test
    void estimateIsColouredByItsAteWithAScaleFromZero() {
        SavedEvaluation s = kittiLikeDrive(500, "se3", false);
        Figure f = byName(EvalFigures.of(s, PlotPlane.AUTO)).get("trajectories");
        Layer.Gradient g = f.layers(Layer.Gradient.class).get(0);
        assertArrayEquals(s.series().poses().ateTransM(), g.value(), TOL);
        assertEquals(0.0, f.colour().min());
        assertEquals(1.0, f.colour().max(), 1e-3); // largest ATE: 0.5 + 0.5 sin(.) reaches 1.0 to 1e-3 in 500 steps
        assertEquals("ATE translation (m)", f.colour().label());
        List<Layer.Points> marks = f.layers(Layer.Points.class);
        assertEquals(List.of("start", "end"), marks.stream().map(Layer.Points::label).toList());
        assertEquals(s.series().poses().estX()[0], marks.get(0).x()[0]);
        assertEquals(s.series().poses().estX()[499], marks.get(1).x()[0]);
    }

    @Test
    void titlesSayWhichAlignmentWasApplied() {
        assertTrue(byName(EvalFigures.of(kittiLikeDrive(50, "none", false), PlotPlane.AUTO)).get("trajectories")
                .title().endsWith("not aligned"));
        assertTrue(byName(EvalFigures.of(kittiLikeDrive(50, "se3", false), PlotPlane.AUTO)).get("trajectories")
                .title().endsWith("aligned: SE(3) (Umeyama)"));
    }

    @Test
    void errorOverTimeHasStatisticLinesAStdBandAndAnAxisFromZero() {
        Figure f = byName(EvalFigures.of(kittiLikeDrive(500, "se3", false), PlotPlane.AUTO)).get("ate_trans");
        assertEquals("frame", f.x().label()); // no stamps: frames, never "time (s)"
        assertEquals(0.0, f.x().min());
        assertEquals(499.0, f.x().max());
        assertEquals("ATE translation (m)", f.y().label());
        assertEquals(0.0, f.y().min());
        List<Layer.Rule> rules = f.layers(Layer.Rule.class);
        assertEquals(List.of(0.5, 0.5, 0.8), rules.stream().map(Layer.Rule::y).toList()); // mean, median, RMSE
        Layer.Band band = f.layers(Layer.Band.class).get(0);
        assertEquals(0.15, band.lower(), TOL); // mean 0.5 - std 0.35
        assertEquals(0.85, band.upper(), TOL);
    }

    @Test
    void rotationsAreDrawnInDegrees() {
        Figure f = byName(EvalFigures.of(kittiLikeDrive(50, "se3", false), PlotPlane.AUTO)).get("rpe_rot");
        assertEquals("RPE rotation (deg)", f.y().label());
        assertEquals(0.5, f.layers(Layer.Line.class).get(0).y()[0], 1e-12);
        assertTrue(f.title().contains("delta 1 frame"), f.title());
    }

    @Test
    void histogramCountsEveryPoseOnce() {
        Figure f = byName(EvalFigures.of(kittiLikeDrive(500, "se3", false), PlotPlane.AUTO)).get("hist_ate_trans");
        Layer.Bars b = f.layers(Layer.Bars.class).get(0);
        double sum = 0;
        for (double c : b.counts()) {
            sum += c;
        }
        assertEquals(500, sum);
        assertEquals(0.0, b.edges()[0]);
        assertEquals(23, b.counts().length); // ceil(sqrt(500)) bins
    }

    @Test
    void driftFiguresOnlyWithDriftInKittiUnits() {
        assertEquals(9, EvalFigures.of(kittiLikeDrive(50, "se3", false), PlotPlane.AUTO).size());
        Map<String, Figure> f = byName(EvalFigures.of(kittiLikeDrive(50, "se3", true), PlotPlane.AUTO));
        assertEquals("translation error (%)", f.get("drift_trans").y().label());
        assertEquals("rotation error (deg/100 m)", f.get("drift_rot").y().label());
        // 0.02 deg/m = 2 deg/100 m
        assertArrayEquals(new double[] {2.0, 1.0}, f.get("drift_rot").layers(Layer.Line.class).get(0).y(), 1e-12);
    }

    @Test
    void longSeriesAreDecimatedWithoutLosingThePeak() {
        int n = 1_000_000;
        double[] t = new double[n];
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = i * 0.01;
            y[i] = 0.1;
        }
        y[777_777] = 9.0;
        double[][] d = Decimate.minMax(t, y, Decimate.SERIES_BUCKETS);
        assertEquals(2 * Decimate.SERIES_BUCKETS, d[0].length);
        double max = 0;
        for (double v : d[1]) {
            max = Math.max(max, v);
        }
        assertEquals(9.0, max);
        int[] idx = Decimate.stride(n, Decimate.PATH_POINTS);
        assertTrue(idx.length <= Decimate.PATH_POINTS, "path points " + idx.length);
        assertEquals(n - 1, idx[idx.length - 1]);
    }

    @Test
    void nearlyEqualErrorsAreDrawnFromZeroNotMagnified() {
        // the suite report's bad case: two methods at 1.350403e-2 m and 1.3504005e-2 m
        Axis a = Axis.fromZero("ATE RMSE (m)", new double[] {1.350403e-2, 1.3504005e-2});
        assertEquals(0.0, a.min());
        assertEquals(1.05 * 1.350403e-2, a.max(), 1e-15);
        Axis s = Axis.spanning("x (m)", new double[] {5.0, 5.0});
        assertTrue(s.max() - s.min() >= 5.0 * Axis.RESOLUTION, "a zero span is widened to the resolution");
    }

    @Test
    void tickLabelsHaveALeadingZeroAndTheStepsDecimals() {
        double[] t = Ticks.of(0, 0.1, 5);
        assertArrayEquals(new String[] {"0.00", "0.02", "0.04", "0.06", "0.08", "0.10"},
                Ticks.labels(t, Ticks.step(0, 0.1, 5)));
    }
}
