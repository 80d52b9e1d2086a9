package org.trajeval.figures;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.trajeval.core.report.EvaluationSeries;
import org.trajeval.core.report.ResultSet;
import org.trajeval.core.report.SavedEvaluation;

/** Box plots of the relative error per sub-trajectory length, checked on their data. */
class SubTrajectoryFiguresTest {
    /** Three segments of 10 m (1, 2, 3 %; 0.1, 0.2, 0.3 deg/m) and two of 20 m (4, 5 %; 0.4, 0.5 deg/m). */
    private static EvaluationSeries.Segments fiveSegments(double shift) {
        return new EvaluationSeries.Segments(new double[] {10, 10, 10, 20, 20}, new double[] {0, 1, 2, 0, 1},
                new double[] {1 + shift, 2 + shift, 3 + shift, 4 + shift, 5 + shift},
                new double[] {0.1, 0.2, 0.3, 0.4, 0.5});
    }

    @Test
    void evalPlotDrawsOneBoxPerLengthWithTheSegmentsQuartiles() {
        SavedEvaluation s = EvalFiguresTest.kittiLikeDrive(100, "se3", false);
        SavedEvaluation withSegments = new SavedEvaluation(s.report(), new EvaluationSeries(s.series().timeUnit(),
                s.series().poses(), s.series().pairs(), fiveSegments(0)));
        List<Figure> figures = EvalFigures.of(withSegments, PlotPlane.AUTO);
        Figure trans = figures.stream().filter(f -> f.name().equals("subtraj_trans")).findFirst().orElseThrow();
        Figure rot = figures.stream().filter(f -> f.name().equals("subtraj_rot")).findFirst().orElseThrow();
        assertEquals(List.of("10 m", "20 m"), trans.x().categories());
        assertEquals("translation error (%)", trans.y().label());
        assertEquals("rotation error (deg/m)", rot.y().label());
        assertEquals(0.0, trans.y().min());
        assertEquals(5 * 1.05, trans.y().max(), 1e-12); // largest value 5 % plus the 5 % margin
        assertTrue(trans.title().endsWith("(5 segments)"), trans.title());
        Layer.Boxes boxes = trans.layers(Layer.Boxes.class).get(0);
        assertNull(boxes.label());
        assertArrayEquals(new double[] {1, 2}, boxes.at(), 1e-12);
        // numpy's linear quartiles of {1, 2, 3}: 1.5, 2, 2.5; of {4, 5}: 4.25, 4.5, 4.75
        assertEquals(2.0, boxes.boxes().get(0).median(), 1e-12);
        assertEquals(1.5, boxes.boxes().get(0).q1(), 1e-12);
        assertEquals(4.75, boxes.boxes().get(1).q3(), 1e-12);
        assertEquals(3, boxes.boxes().get(0).n());
        assertEquals(0.4, rot.layers(Layer.Boxes.class).get(0).boxes().get(1).low(), 1e-12);
    }

    @Test
    void withoutSegmentsThereIsNoSubTrajectoryFigure() {
        List<Figure> figures = EvalFigures.of(EvalFiguresTest.kittiLikeDrive(100, "se3", false), PlotPlane.AUTO);
        assertTrue(figures.stream().noneMatch(f -> f.name().startsWith("subtraj")));
    }

    @Test
    void resDrawsTheResultsSideBySideWithinEachLengthColouredByName() {
        List<ResultSet> results = List.of(
                new ResultSet("orb", "a", "trajeval", "", "s", List.of(), fiveSegments(0)),
                new ResultSet("orb", "b", "trajeval", "", "s", List.of(), fiveSegments(1)),
                new ResultSet("sptam", "c", "trajeval", "", "s", List.of(), fiveSegments(2)),
                new ResultSet("evo", "d.zip", "evo", "", null, List.of()));
        Figure trans = ResFigures.of(results).stream().filter(f -> f.name().equals("subtraj_trans")).findFirst()
                .orElseThrow();
        List<Layer.Boxes> layers = trans.layers(Layer.Boxes.class);
        assertEquals(3, layers.size()); // the evo archive has no segments
        assertEquals("orb", layers.get(0).label());
        assertNull(layers.get(1).label()); // a second seed of orb: one legend entry per name
        assertEquals("sptam", layers.get(2).label());
        // three results with segments, spacing 0.8 / 3 around each length's category: offsets -0.8/3, 0, +0.8/3
        assertArrayEquals(new double[] {1 - 0.8 / 3, 2 - 0.8 / 3}, layers.get(0).at(), 1e-12);
        assertArrayEquals(new double[] {1, 2}, layers.get(1).at(), 1e-12);
        assertArrayEquals(new double[] {1 + 0.8 / 3, 2 + 0.8 / 3}, layers.get(2).at(), 1e-12);
        assertEquals(layers.get(0).boxes().get(0).rgb(), layers.get(1).boxes().get(0).rgb());
        assertEquals(4.0, layers.get(2).boxes().get(0).median(), 1e-12); // {3, 4, 5}
    }
}
