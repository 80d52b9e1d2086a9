package org.trajeval.core.eval;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.junit.jupiter.api.Test;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.metric.AteResult;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * {@link Evaluator#evaluateConsumingReference}: a pair whose reference is handed over gives the
 * report of the same pair not handed over, bit for bit (JSON writes the shortest text that reads
 * back to the same bits), on one and on two threads, for sizes around the chunk edges
 * ({@link Parallelism#chunks}); and the handed-over reference's x and y columns really are the
 * error arrays: they end up holding the general path's per-pose ATE errors.
 */
class ReferenceHandoverTest {

    @Test
    void handedOverPairGivesTheSameReportBitsAsAPairNotHandedOver() {
        ExecutorService pool = Executors.newFixedThreadPool(2);
        try {
            int chunk = Parallelism.CHUNK;
            for (int n : new int[] {3, 1000, chunk - 1, chunk, chunk + 1, 2 * chunk + 3}) {
                for (int threads = 1; threads <= 2; threads++) {
                    for (RpeUnit unit : new RpeUnit[] {RpeUnit.SECONDS, RpeUnit.FRAMES}) {
                        EvaluationOptions o = EvaluationOptions.preset(Convention.LESSON).withRpe(
                                unit == RpeUnit.SECONDS ? 1 : 3, unit);
                        Parallelism par = threads == 1 ? Parallelism.SEQUENTIAL : new Parallelism(pool, threads);
                        String kept = ReportJson.toJson(Evaluator.evaluate(pair("gt", n), pair("est", n, 5), o, par));
                        LoadedTrajectory ref = pair("gt", n);
                        double[] x = ((PlanarTrajectory) ref.trajectory()).handOverColumns()[0];
                        double before = x[n / 2];
                        String consumed = ReportJson.toJson(
                                Evaluator.evaluateConsumingReference(ref, pair("est", n, 5), o, par));
                        assertEquals(kept, consumed, n + " poses, " + threads + " threads, " + unit);
                        // the probe: the reference's own column was written (the errors are not its values)
                        assertTrue(x[n / 2] != before, "x column reused at " + n);
                    }
                }
            }
        } finally {
            pool.shutdownNow();
        }
    }

    @Test
    void handedOverColumnsHoldTheGeneralPathsAteErrors() {
        int n = 5000;
        EvaluationOptions o = EvaluationOptions.preset(Convention.LESSON).withRpe(1, RpeUnit.SECONDS);
        AteResult ate = Evaluator.run(pair("gt", n), pair("est", n, 5), o).ate();
        LoadedTrajectory ref = pair("gt", n);
        double[][] columns = ((PlanarTrajectory) ref.trajectory()).handOverColumns();
        Evaluator.evaluateConsumingReference(ref, pair("est", n, 5), o, Parallelism.SEQUENTIAL);
        int m = ate.transErrorsM().length;
        assertArrayEquals(sorted(ate.transErrorsM()), sorted(Arrays.copyOf(columns[0], m)));
        assertArrayEquals(sorted(ate.rotErrorsRad()), sorted(Arrays.copyOf(columns[1], m)));
    }

    @Test
    void onlyAnInterpolatedPlanarPairWithItsOwnColumnsIsHandedOver() {
        EvaluationOptions interpolate = EvaluationOptions.preset(Convention.LESSON);
        PlanarTrajectory ref = (PlanarTrajectory) pair("gt", 100).trajectory();
        PlanarTrajectory est = (PlanarTrajectory) pair("est", 100, 5).trajectory();
        assertNotNull(ColumnarEvaluator.handedOverColumns(ref, est, interpolate, 100));
        // more pairs than the reference's columns hold
        assertNull(ColumnarEvaluator.handedOverColumns(ref, est, interpolate, 101));
        // nearest matching reads the reference's columns through its index map
        assertNull(ColumnarEvaluator.handedOverColumns(ref, est,
                interpolate.withAssociation(AssociationMethod.NEAREST), 100));
        // a pair that shares a column with its estimate (here: the same trajectory)
        assertNull(ColumnarEvaluator.handedOverColumns(ref, ref, interpolate, 100));
        // an SE(3) reference
        assertNull(ColumnarEvaluator.handedOverColumns(ref.toSpatial(), est.toSpatial(), interpolate, 100));
    }

    private static LoadedTrajectory pair(String name, int n) {
        return TestTrajectories.loaded(name, TestTrajectories.lessonPath(n, 0.01));
    }

    /** The lesson path moved, with seeded noise on positions and yaws, and the stamps shifted inside the reference's span. */
    private static LoadedTrajectory pair(String name, int n, long seed) {
        PlanarTrajectory truth = TestTrajectories.lessonPath(n, 0.01);
        Random rnd = new Random(seed);
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = truth.t(i) + (i == n - 1 ? 0.0 : 0.003);
            x[i] = 1 + truth.x(i) * Math.cos(0.3) - truth.y(i) * Math.sin(0.3) + 0.05 * rnd.nextGaussian();
            y[i] = -2 + truth.x(i) * Math.sin(0.3) + truth.y(i) * Math.cos(0.3) + 0.05 * rnd.nextGaussian();
            yaw[i] = truth.yaw(i) + 0.3 + 0.02 * rnd.nextGaussian();
        }
        return TestTrajectories.loaded(name, PlanarTrajectory.of(t, x, y, yaw));
    }

    private static double[] sorted(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        return s;
    }
}
