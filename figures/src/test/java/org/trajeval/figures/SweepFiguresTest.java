package org.trajeval.figures;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.trajeval.core.report.FactorSweep;
import org.trajeval.core.report.SuiteReport;

/** The sweep figures' data: the median line per method against the level, and the failure rates. */
class SweepFiguresTest {
    private static FactorSweep.Level level(double x, int failures, Double median) {
        SuiteReport.Proportion p = new SuiteReport.Proportion(failures / 3.0, 0.95, new SuiteReport.Bounds(0, 1),
                new SuiteReport.Bounds(0, 1), null);
        return new FactorSweep.Level(x, 1, 3, failures, p, List.of(new FactorSweep.LevelMetric("ate_trans_rmse_m",
                median == null ? 0 : 3 - failures, median, median == null ? null : median - 0.01,
                median == null ? null : median + 0.01, 0.75)));
    }

    @Test
    void oneMedianFigureAndOneFailureFigurePerFactorTheBrokenLevelLeftOut() {
        FactorSweep s = new FactorSweep("obstacle_density", List.of("a", "b", "c"), List.of(0.0, 0.4, 0.8), 0.5,
                List.of(new FactorSweep.MethodSweep("gamma", List.of(level(0.0, 0, 0.1), level(0.4, 1, 0.2),
                        level(0.8, 3, null)), 0.8, List.of())));
        SuiteReport r = new SuiteReport(SuiteReport.SCHEMA, 1, "x", null, null, List.of(), List.of(), List.of(),
                List.of(), null, List.of(s), null, List.of(), List.of());
        List<Figure> f = SweepFigures.of(r);
        assertEquals(List.of("sweep_obstacle_density", "sweep_obstacle_density_failures"),
                f.stream().map(Figure::name).toList());
        Layer.Line median = f.get(0).layers(Layer.Line.class).get(0);
        // every run failed at 0.8: no median there, the line ends at 0.4 (values in mm: the label's factor)
        assertArrayEquals(new double[] {0.0, 0.4}, median.x(), 0.0);
        assertEquals(0.1 * MetricLabel.of("ate_trans_rmse_m").factor(), median.y()[0], 1e-12);
        assertTrue(median.label().contains("breaks down at 0.8"), median.label());
        Layer.Line rates = f.get(1).layers(Layer.Line.class).get(0);
        assertArrayEquals(new double[] {0.0, 1.0 / 3.0, 1.0}, rates.y(), 1e-15);
        assertEquals(0.5, f.get(1).layers(Layer.Rule.class).get(0).y(), 0.0);
    }
}
