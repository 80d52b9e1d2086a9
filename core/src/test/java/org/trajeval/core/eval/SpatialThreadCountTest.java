package org.trajeval.core.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.junit.jupiter.api.Test;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * A 3D pair scored on two and three threads gives one thread's report, byte for byte (the JSON
 * writes the shortest text that reads back to the same bits): the fit beside the check's spreads
 * and the error arrays' allocation, the statistics beside one another, the chunked nearest search
 * and its counts. 131 075 poses cut the chunks of 65 536 unevenly; the estimate is as long as, half
 * as long as and twice as long as the reference (the nearest search walks the longer one).
 */
class SpatialThreadCountTest {

    @Test
    void everyModelAssociationAndPairRuleGivesTheSameBitsOnEveryThreadCount() {
        SpatialTrajectory truth = TestTrajectories.helix(131_075, 0.01);
        SpatialTrajectory est = ColumnarEvaluatorTest.warped3(truth, new Random(9));
        SpatialTrajectory[][] pairs = {{truth, est}, {truth, everyOther(est)}, {everyOther(truth), est}};
        ExecutorService pool = Executors.newFixedThreadPool(2);
        int checked = 0;
        try {
            for (SpatialTrajectory[] pair : pairs) {
                LoadedTrajectory r = TestTrajectories.loaded("gt", pair[0]);
                LoadedTrajectory e = TestTrajectories.loaded("est", pair[1]);
                for (AssociationMethod assoc : new AssociationMethod[] {AssociationMethod.INTERPOLATE,
                    AssociationMethod.NEAREST}) {
                    for (AlignmentModel model : new AlignmentModel[] {AlignmentModel.SE3, AlignmentModel.SIM3,
                        AlignmentModel.SE2, AlignmentModel.NONE}) {
                        boolean seconds = model == AlignmentModel.SE3 || model == AlignmentModel.SE2;
                        EvaluationOptions o = EvaluationOptions.preset(Convention.EVO).withAssociation(assoc)
                                .withMaxDiffS(0.02).withAlignment(model)
                                .withRpe(1, seconds ? RpeUnit.SECONDS : RpeUnit.FRAMES)
                                .withPairSelection(seconds ? PairSelection.ALL_PAIRS : PairSelection.CONSECUTIVE)
                                .withNToAlign(model == AlignmentModel.SIM3 ? 70_001 : -1);
                        String what = assoc + " " + model + " ref " + pair[0].size() + " est " + pair[1].size();
                        sameOnEveryThreadCount(r, e, o, pool, what);
                        checked++;
                    }
                }
            }
        } finally {
            pool.shutdownNow();
        }
        assertEquals(3 * 2 * 4, checked);
    }

    @Test
    void alignmentWarningsOfTheSideBySideCheckAreThoseOfOneThread() {
        // positions 1e-5 m off a straight line: the rotation about it is unobservable; the estimate
        // at 3x the scale: a sim3 scale far from one
        int n = 70_003;
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] z = new double[n];
        double[] qw = new double[n];
        double[] qx = new double[n];
        double[] qy = new double[n];
        double[] qz = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = 0.01 * i;
            x[i] = 0.01 * i;
            y[i] = 1e-5 * Math.sin(t[i]);
            z[i] = 1e-5 * Math.cos(t[i]);
            qw[i] = Math.cos(0.1 * t[i]);
            qz[i] = Math.sin(0.1 * t[i]);
        }
        SpatialTrajectory line = SpatialTrajectory.of(t, x, y, z, qw, qx, qy, qz);
        SpatialTrajectory scaled = SpatialTrajectory.of(t, scale(x), scale(y), scale(z), qw, qx, qy, qz);
        LoadedTrajectory r = TestTrajectories.loaded("gt", line);
        LoadedTrajectory e = TestTrajectories.loaded("est", scaled);
        ExecutorService pool = Executors.newFixedThreadPool(2);
        try {
            EvaluationOptions o = EvaluationOptions.preset(Convention.EVO).withAlignment(AlignmentModel.SIM3);
            EvaluationReport one = sameOnEveryThreadCount(r, e, o, pool, "line, sim3");
            assertTrue(one.warnings().stream().anyMatch(w -> w.code().equals(AlignmentCheck.UNOBSERVABLE)),
                    one.warnings().toString());
            assertTrue(one.warnings().stream().anyMatch(w -> w.code().equals(AlignmentCheck.SCALE)),
                    one.warnings().toString());
        } finally {
            pool.shutdownNow();
        }
    }

    /** @return one thread's report, after checking that 2 and 3 threads give the same JSON */
    private static EvaluationReport sameOnEveryThreadCount(LoadedTrajectory r, LoadedTrajectory e,
            EvaluationOptions o, ExecutorService pool, String what) {
        assertTrue(ColumnarEvaluator.applies(r, e, o), what);
        assertNotNull(ColumnarEvaluator.evaluate(r.trajectory(), e.trajectory(), o, r.source(), e.source(),
                Parallelism.SEQUENTIAL, false), "the columnar evaluator declined " + what);
        EvaluationReport one = Evaluator.evaluate(r, e, o, Parallelism.SEQUENTIAL);
        String json = ReportJson.toJson(one);
        for (int threads = 2; threads <= 3; threads++) {
            assertEquals(json, ReportJson.toJson(Evaluator.evaluate(r, e, o, new Parallelism(pool, threads))),
                    what + " on " + threads + " threads");
        }
        return one;
    }

    private static SpatialTrajectory everyOther(SpatialTrajectory a) {
        int n = (a.size() + 1) / 2;
        double[][] c = new double[8][n];
        double[] q = new double[4];
        for (int i = 0; i < n; i++) {
            int k = 2 * i;
            a.quaternion(k, q);
            double[] row = {a.t(k), a.x(k), a.y(k), a.z(k), q[0], q[1], q[2], q[3]};
            for (int j = 0; j < 8; j++) {
                c[j][i] = row[j];
            }
        }
        return SpatialTrajectory.of(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
    }

    private static double[] scale(double[] v) {
        double[] s = new double[v.length];
        for (int i = 0; i < v.length; i++) {
            s[i] = 3.0 * v[i];
        }
        return s;
    }
}
