package org.trajeval.core.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PlanarTrajectory;

/** Per-axis, heading and speed errors, by hand on a straight run. */
class ExtraMetricsTest {
    private static final double TOL = 1e-9;

    /** Reference x = t at 1 m/s, 10 Hz for 10 s; estimate x = 1.1 t, y = 0.2 m, yaw 0.05 rad. */
    private static LoadedTrajectory[] pair() {
        int n = 101;
        double[] t = new double[n];
        double[] rx = new double[n];
        double[] ex = new double[n];
        double[] ey = new double[n];
        double[] eyaw = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = i * 0.1;
            rx[i] = t[i];
            ex[i] = 1.1 * t[i];
            ey[i] = 0.2;
            eyaw[i] = 0.05;
        }
        return new LoadedTrajectory[] {
            new LoadedTrajectory("ref", TrajectoryFormat.CSV, "test", PlanarTrajectory.of(t, rx, new double[n],
                    new double[n]), "0", false),
            new LoadedTrajectory("est", TrajectoryFormat.CSV, "test", PlanarTrajectory.of(t.clone(), ex, ey, eyaw),
                    "0", false)};
    }

    @Test
    void straightRunGivesTheHandDerivedBiasHeadingAndSpeedErrors() {
        LoadedTrajectory[] p = pair();
        EvaluationReport r = Evaluator.evaluate(p[0], p[1], EvaluationOptions.preset(Convention.LESSON)
                .withAlignment(AlignmentModel.NONE).withExtraMetrics(true));
        EvaluationReport.Extra x = r.extra();
        // e_x = 0.1 t over t = 0, 0.1, ..., 10 s: mean 0.1 x 5 s = 0.5 m; e_y = 0.2 m everywhere; e_z = 0
        assertEquals(0.5, x.transXM().mean(), TOL);
        assertEquals(0.2, x.transYM().mean(), TOL);
        assertEquals(0.0, x.transYM().std(), TOL);
        assertEquals(0.0, x.transZM().max(), TOL);
        // heading 0.05 rad off everywhere
        assertEquals(0.05, x.headingRad().mean(), TOL);
        // |v_est| = 1.1 m/s, |v_ref| = 1 m/s over any horizon: +0.1 m/s for every pair. The horizon is the
        // RPE's mean, 1 s up to the rounding of 0.1 s steps (a pair may take 1.1 s)
        assertEquals(1.0, x.speedHorizonS(), 0.1);
        assertEquals(0.1, x.speedMps().mean(), TOL);
        assertEquals(0.1, x.speedMps().max(), TOL);
        assertEquals(0.1, x.speedMps().min(), TOL);
    }

    @Test
    void extraMetricsAreOffByDefault() {
        LoadedTrajectory[] p = pair();
        assertNull(Evaluator.evaluate(p[0], p[1], EvaluationOptions.preset(Convention.LESSON)).extra());
    }
}
