package org.trajeval.core.assoc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.metric.Coverage;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PlanarTrajectory;

/** Interpolation never bridges a reference gap longer than the limit; what it drops is counted and located. */
class MaxGapTest {
    private static final double TIME_TOL_S = 1e-12;

    /** Reference at 10 Hz on 0..20 s with a hole (8, 13) s; the estimate at 10 Hz, 0.05 s late, 0.1 m off in y. */
    private static LoadedTrajectory[] pairWithHole() {
        int n = 0;
        double[] t = new double[201];
        for (int i = 0; i <= 200; i++) {
            double ti = i * 0.1;
            if (ti > 8.0 + 1e-9 && ti < 13.0 - 1e-9) {
                continue;
            }
            t[n++] = ti;
        }
        double[] rt = java.util.Arrays.copyOf(t, n);
        double[] zero = new double[n];
        PlanarTrajectory ref = PlanarTrajectory.of(rt, rt.clone(), zero, zero.clone());
        double[] et = new double[200];
        double[] ex = new double[200];
        double[] ey = new double[200];
        for (int i = 0; i < 200; i++) {
            et[i] = i * 0.1 + 0.05;
            ex[i] = et[i];
            ey[i] = 0.1;
        }
        PlanarTrajectory est = PlanarTrajectory.of(et, ex, ey, new double[200]);
        return new LoadedTrajectory[] {new LoadedTrajectory("ref.csv", TrajectoryFormat.CSV, "test", ref, "0", false),
            new LoadedTrajectory("est.csv", TrajectoryFormat.CSV, "test", est, "0", false)};
    }

    @Test
    void medianPeriodIsTheTypicalSpacing() {
        // 10 Hz with one 5 s hole: the median of the spacings is 0.1 s
        assertEquals(0.1, MaxGap.medianPeriodS(pairWithHole()[0].trajectory()), 1e-9);
    }

    @Test
    void estimatePosesInsideALongGapAreDroppedCountedAndLocated() {
        LoadedTrajectory[] p = pairWithHole();
        // default limit 10 x 0.1 s = 1 s < 5 s hole; estimate stamps 8.05 .. 12.95 s lie inside: 50 poses
        EvaluationReport r = Evaluator.evaluate(p[0], p[1], EvaluationOptions.preset(Convention.LESSON)
                .withAlignment(org.trajeval.core.align.AlignmentModel.NONE));
        EvaluationReport.AssociationInfo a = r.association();
        assertEquals(50, a.droppedInGaps());
        assertEquals(1, a.gaps().size());
        assertEquals(8.0, a.gaps().get(0).startS(), TIME_TOL_S);
        assertEquals(13.0, a.gaps().get(0).endS(), TIME_TOL_S);
        assertEquals(50, a.gaps().get(0).dropped());
        assertEquals(1.0, a.gapLimitS(), 1e-9);
        // all 200 estimate stamps (0.05 .. 19.95 s) lie within [0, 20] s, 50 of them in the hole
        assertEquals(150, a.matched());
        assertEquals(0.1, r.ate().transM().rmse(), 1e-12);
        assertEquals("poses_dropped_in_reference_gaps", r.warnings().get(0).code());
        assertTrue(r.warnings().get(0).message().contains("--max-gap"), r.warnings().get(0).message());
    }

    @Test
    void aLargerLimitBridgesTheGapAsBefore() {
        LoadedTrajectory[] p = pairWithHole();
        EvaluationReport r = Evaluator.evaluate(p[0], p[1], EvaluationOptions.preset(Convention.LESSON)
                .withAlignment(org.trajeval.core.align.AlignmentModel.NONE).withMaxGap(MaxGap.ofSeconds(6.0)));
        assertEquals(0, r.association().droppedInGaps());
        assertEquals(200, r.association().matched());
        assertEquals(List.of(), r.warnings());
    }

    @Test
    void coverageCountsTheHoleAndTheEnds() {
        // reference 0..100 s; estimate every 0.1 s on 0..40 s and 60..100 s: the 20 s hole is uncovered
        double[] s = new double[802];
        int k = 0;
        for (int i = 0; i <= 400; i++) {
            s[k++] = i * 0.1;
        }
        for (int i = 600; i <= 1000; i++) {
            s[k++] = i * 0.1;
        }
        int n = k;
        Coverage c = Coverage.compute(i -> s[i], n, 0.0, 100.0);
        assertEquals(0.8, c.fraction(), 1e-9);
        assertEquals(20.0, c.longestGapS(), 1e-9);
        assertEquals(40.0, c.longestGapStartS(), 1e-9);
        // only the first 40 s of it: the 60 s after the last pose are uncovered: 40 %
        Coverage half = Coverage.compute(i -> s[i], 401, 0.0, 100.0);
        assertEquals(0.4, half.fraction(), 1e-9);
        assertEquals(60.0, half.longestGapS(), 1e-9);
    }
}
