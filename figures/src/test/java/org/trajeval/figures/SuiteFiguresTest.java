package org.trajeval.figures;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.trajeval.core.report.SequencePlot;

/** The suite report's sequence figures, checked on their data. */
class SuiteFiguresTest {

    /** A KITTI-like sequence (x-z ground plane); per method, seeds whose error is seed * 0.1 m everywhere. */
    static SequencePlot sequence(int methods, int seeds, String alignment) {
        int n = 100;
        double[] x = new double[n];
        double[] y = new double[n];
        double[] z = new double[n];
        double[] t = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = i;
            z[i] = 20 * Math.sin(i / 20.0);
            t[i] = 0.1 * i;
        }
        List<SequencePlot.Trace> traces = new ArrayList<>();
        for (int m = 0; m < methods; m++) {
            for (int s = 1; s <= seeds; s++) {
                double[] e = new double[n];
                java.util.Arrays.fill(e, 0.1 * s + m);
                traces.add(new SequencePlot.Trace("m" + m, s, x, y, z, t, e, alignment));
            }
        }
        return new SequencePlot("00", "s", x, y, z, traces);
    }

    @Test
    void everySeedIsDrawnAndTheMedianSeedIsBold() {
        Figure f = SuiteFigures.overlay(sequence(2, 5, "se3"), PlotPlane.AUTO);
        assertEquals("z (m)", f.y().label()); // x-z: the plane of the largest extent
        List<Layer.Line> lines = f.layers(Layer.Line.class);
        assertEquals(1 + 2 * 5, lines.size()); // reference + every seed of both methods
        List<Layer.Line> labelled = lines.stream().filter(l -> l.label() != null).toList();
        assertEquals(List.of("reference", "m0 (median of 5 seeds)", "m1 (median of 5 seeds)"),
                labelled.stream().map(Layer::label).toList());
        assertNull(f.colour());
        assertTrue(f.title().endsWith("aligned: SE(3) (Umeyama)"), f.title());
    }

    @Test
    void medianSeedIsTheOneWithTheMedianRmsError() {
        // seed s has error 0.1 s m at every pose: RMS errors 0.1 .. 0.5 m, median at seed 3
        assertEquals(3, SuiteFigures.medianSeed(sequence(1, 5, "se2").estimates()).seed());
    }

    @Test
    void oneRunAloneIsColouredByItsError() {
        Figure f = SuiteFigures.overlay(sequence(1, 1, "none"), PlotPlane.AUTO);
        assertEquals(1, f.layers(Layer.Gradient.class).size());
        assertNotNull(f.colour());
        assertTrue(f.title().endsWith("not aligned"), f.title());
    }

    @Test
    void errorOverTimeShowsMedianAndEnvelopeOverSeedsOnRelativeTime() {
        Figure f = SuiteFigures.errorOverTime(sequence(1, 5, "se3"));
        assertEquals("time from start (s)", f.x().label());
        assertEquals(0.0, f.x().min());
        assertEquals(9.9, f.x().max(), 1e-12); // last stamp 0.1 * 99 s
        assertEquals(0.0, f.y().min());
        Layer.Area a = f.layers(Layer.Area.class).get(0);
        Layer.Line median = f.layers(Layer.Line.class).get(0);
        assertEquals(0.1, a.lower()[0], 1e-12); // seed 1
        assertEquals(0.5, a.upper()[0], 1e-12); // seed 5
        assertEquals(0.3, median.y()[0], 1e-12); // seed 3
    }

    @Test
    void metricKeysReadAsLabelsWithUnitsAndDegrees() {
        assertEquals("ATE translation RMSE (m)", MetricLabel.of("ate_trans_rmse_m").label());
        MetricLabel rot = MetricLabel.of("rpe_rot_rmse_rad");
        assertEquals("RPE rotation RMSE (deg)", rot.label());
        assertEquals(180 / Math.PI, rot.factor(), 1e-15);
        assertEquals("drift translation (%)", MetricLabel.of("drift_trans_pct").label());
    }
}
