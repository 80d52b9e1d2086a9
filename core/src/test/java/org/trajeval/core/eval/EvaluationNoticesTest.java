package org.trajeval.core.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * What an evaluation did differently from what was asked is in the report's warnings, for every
 * front end (issue 11, items 19 and 20): a clamped n-to-align and an RPE horizon with no pair.
 */
class EvaluationNoticesTest {

    /** 11 poses at 10 Hz on x = t (1 s long); the estimate is the same path 0.1 m to the side. */
    private static LoadedTrajectory[] pair() {
        int n = 11;
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = i * 0.1;
            x[i] = t[i];
            y[i] = 0.1;
        }
        return new LoadedTrajectory[] {
            new LoadedTrajectory("ref", TrajectoryFormat.CSV, "test", PlanarTrajectory.of(t, x, new double[n],
                    new double[n]), "0", false),
            new LoadedTrajectory("est", TrajectoryFormat.CSV, "test", PlanarTrajectory.of(t.clone(), x.clone(), y,
                    new double[n]), "0", false)};
    }

    private static List<String> codes(EvaluationReport r) {
        return r.warnings().stream().map(EvaluationReport.Warning::code).toList();
    }

    @Test
    void anNToAlignBeyondTheAssociatedPosesIsAWarningAndTheFitUsesThemAll() {
        LoadedTrajectory[] p = pair();
        EvaluationReport r = Evaluator.evaluate(p[0], p[1], EvaluationOptions.preset(Convention.LESSON)
                .withAlignment(AlignmentModel.SE2).withNToAlign(5000));
        assertEquals(11, r.alignment().posesUsed());
        assertTrue(codes(r).contains("n_to_align_clamped"), codes(r).toString());
        assertTrue(r.warnings().stream().anyMatch(w -> w.message().contains("5000") && w.message().contains("11")));
    }

    @Test
    void anNToAlignWithinThePosesGivesNoWarning() {
        LoadedTrajectory[] p = pair();
        EvaluationReport r = Evaluator.evaluate(p[0], p[1], EvaluationOptions.preset(Convention.LESSON)
                .withAlignment(AlignmentModel.SE2).withNToAlign(5));
        assertEquals(5, r.alignment().posesUsed());
        assertTrue(!codes(r).contains("n_to_align_clamped"), codes(r).toString());
    }

    @Test
    void anRpeHorizonLongerThanTheTrajectoryIsAWarningWithNoPairs() {
        LoadedTrajectory[] p = pair();
        // the trajectory spans 1 s: a 100 s horizon has no pair; a 0.5 s horizon has pairs
        EvaluationReport none = Evaluator.evaluate(p[0], p[1], EvaluationOptions.preset(Convention.LESSON)
                .withRpe(100.0, RpeUnit.SECONDS));
        assertEquals(0, none.rpe().pairs());
        assertTrue(codes(none).contains("no_rpe_pairs"), codes(none).toString());
        EvaluationReport some = Evaluator.evaluate(p[0], p[1], EvaluationOptions.preset(Convention.LESSON)
                .withRpe(0.5, RpeUnit.SECONDS));
        assertTrue(some.rpe().pairs() > 0);
        assertTrue(!codes(some).contains("no_rpe_pairs"), codes(some).toString());
    }
}
