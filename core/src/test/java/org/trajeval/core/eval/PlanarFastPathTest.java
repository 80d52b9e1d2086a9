package org.trajeval.core.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * The planar fast path must give the general SE(3) path's numbers: both are run on seeded random
 * planar pairs for every option combination the fast path accepts.
 */
class PlanarFastPathTest {
    static final double REL = 1e-9;
    static final double ABS = 1e-12;

    @Test
    void fastPathAgreesWithTheGeneralPathForEveryEligibleOptionCombination() {
        Random rnd = new Random(2024);
        int checked = 0;
        for (int trial = 0; trial < 6; trial++) {
            PlanarTrajectory truth = TestTrajectories.lessonPath(300 + 37 * trial, 0.1);
            PlanarTrajectory est = warped(truth, rnd);
            LoadedTrajectory r = TestTrajectories.loaded("gt", truth);
            LoadedTrajectory e = TestTrajectories.loaded("est", est);
            for (AlignmentModel model : new AlignmentModel[] {AlignmentModel.NONE, AlignmentModel.SE2,
                AlignmentModel.SIM2, AlignmentModel.ORIGIN}) {
                for (RpeUnit unit : new RpeUnit[] {RpeUnit.SECONDS, RpeUnit.FRAMES}) {
                    for (PairSelection sel : PairSelection.values()) {
                        double delta = unit == RpeUnit.SECONDS ? 0.5 + trial * 0.3 : 1 + trial * 3;
                        EvaluationOptions o = EvaluationOptions.preset(Convention.LESSON).withAlignment(model)
                                .withRpe(delta, unit).withPairSelection(sel).withTOffsetS(trial * 0.013)
                                .withNToAlign(trial % 2 == 0 ? -1 : 100);
                        assertTrue(PlanarEvaluator.applies(r, e, o));
                        EvaluationReport fast = Evaluator.evaluate(r, e, o);
                        EvaluationReport general = Evaluator.run(r, e, o).report();
                        same(general, fast, model + " " + unit + " " + sel + " trial " + trial);
                        checked++;
                    }
                }
            }
        }
        assertEquals(6 * 4 * 2 * 2, checked);
    }

    @Test
    void fastPathAgreesWithTheGeneralPathAcrossManyChunks() {
        // 150 001 poses = three chunks of 65 536 start poses: interpolation, RPE partners and
        // path lengths restart at each chunk boundary
        PlanarTrajectory truth = TestTrajectories.lessonPath(150_001, 0.01);
        LoadedTrajectory r = TestTrajectories.loaded("gt", truth);
        LoadedTrajectory e = TestTrajectories.loaded("est", warped(truth, new Random(7)));
        for (RpeUnit unit : new RpeUnit[] {RpeUnit.SECONDS, RpeUnit.FRAMES}) {
            EvaluationOptions o = EvaluationOptions.preset(Convention.LESSON).withRpe(unit == RpeUnit.SECONDS ? 1 : 50,
                    unit).withPairSelection(PairSelection.ALL_PAIRS).withTOffsetS(0.004);
            assertTrue(PlanarEvaluator.applies(r, e, o));
            same(Evaluator.run(r, e, o).report(), Evaluator.evaluate(r, e, o), "150 001 poses " + unit);
        }
    }

    @Test
    void threadCountDoesNotChangeASingleBit() throws Exception {
        PlanarTrajectory truth = TestTrajectories.lessonPath(200_003, 0.01);
        LoadedTrajectory r = TestTrajectories.loaded("gt", truth);
        LoadedTrajectory e = TestTrajectories.loaded("est", warped(truth, new Random(11)));
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(3);
        try {
            for (RpeUnit unit : new RpeUnit[] {RpeUnit.SECONDS, RpeUnit.FRAMES}) {
                for (PairSelection sel : PairSelection.values()) {
                    EvaluationOptions o = EvaluationOptions.preset(Convention.LESSON)
                            .withRpe(unit == RpeUnit.SECONDS ? 0.7 : 20, unit).withPairSelection(sel);
                    String one = ReportJson.toJson(Evaluator.evaluate(r, e, o));
                    for (int threads = 2; threads <= 4; threads++) {
                        // JSON writes the shortest text that reads back to the same bits
                        assertEquals(one, ReportJson.toJson(Evaluator.evaluate(r, e, o, new Parallelism(pool, threads))),
                                unit + " " + sel + " on " + threads + " threads");
                    }
                }
            }
        } finally {
            pool.shutdownNow();
        }
    }

    private static void same(EvaluationReport a, EvaluationReport b, String what) {
        assertEquals(a.association().matched(), b.association().matched(), what);
        assertEquals(a.association().dropped(), b.association().dropped(), what);
        close(a.association().maxGapS(), b.association().maxGapS(), what + " max gap");
        close(a.association().interpErrorBoundM(), b.association().interpErrorBoundM(), what + " bound");
        close(a.alignment().scale(), b.alignment().scale(), what + " scale");
        stats(a.ate().transM(), b.ate().transM(), what + " ATE trans");
        stats(a.ate().rotRad(), b.ate().rotRad(), what + " ATE rot");
        assertEquals(a.rpe().pairs(), b.rpe().pairs(), what + " pairs");
        stats(a.rpe().transM(), b.rpe().transM(), what + " RPE trans");
        stats(a.rpe().rotRad(), b.rpe().rotRad(), what + " RPE rot");
        close(a.rpe().meanHorizonS(), b.rpe().meanHorizonS(), what + " horizon s");
        close(a.rpe().meanHorizonM(), b.rpe().meanHorizonM(), what + " horizon m");
    }

    private static void stats(EvaluationReport.Stats a, EvaluationReport.Stats b, String what) {
        assertEquals(a.n(), b.n(), what + " n");
        close(a.rmse(), b.rmse(), what + " rmse");
        close(a.mean(), b.mean(), what + " mean");
        close(a.median(), b.median(), what + " median");
        close(a.std(), b.std(), what + " std");
        close(a.min(), b.min(), what + " min");
        close(a.max(), b.max(), what + " max");
    }

    private static void close(double a, double b, String what) {
        assertTrue(Math.abs(a - b) <= Math.max(ABS, REL * Math.abs(a)), what + ": general " + a + " fast " + b);
    }

    /** Noise, drift, a rigid offset and a slight time warp with stamps spilling past both ends. */
    private static PlanarTrajectory warped(PlanarTrajectory truth, Random rnd) {
        int n = truth.size();
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        for (int i = 0; i < n; i++) {
            double s = truth.t(i);
            t[i] = s + 0.01 * Math.sin(0.05 * s) + (i == 0 ? -0.3 : 0.002);
            x[i] = 3 + truth.x(i) * Math.cos(0.4) - truth.y(i) * Math.sin(0.4) + 0.03 * s + 0.08 * rnd.nextGaussian();
            y[i] = -1 + truth.x(i) * Math.sin(0.4) + truth.y(i) * Math.cos(0.4) + 0.08 * rnd.nextGaussian();
            yaw[i] = truth.yaw(i) + 0.4 + 0.03 * Math.sin(0.2 * s) + 0.02 * rnd.nextGaussian() + 2 * Math.PI * (i % 3);
        }
        return PlanarTrajectory.of(t, x, y, yaw);
    }
}
