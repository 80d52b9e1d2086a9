package org.trajeval.core.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * The columnar evaluator ({@link Evaluator#evaluate}) must give the general path's numbers
 * ({@link Evaluator#run}, which materialises every pose): both are run on seeded random planar and
 * SE(3) pairs for every option combination the columnar evaluator accepts. The per-pose errors are
 * computed by the same operations in the same order, so the statistics agree bit for bit; only
 * the mean RPE horizon is summed in another order (chunk by chunk) and agrees to 1e-9 relative.
 */
class ColumnarEvaluatorTest {
    static final double REL = 1e-9;
    static final double ABS = 1e-12;

    @Test
    void planarPairsAgreeWithTheGeneralPathForEveryEligibleOptionCombination() {
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
                        assertTrue(ColumnarEvaluator.applies(r, e, o));
                        takesColumnarPath(r, e, o);
                            takesColumnarPath(r, e, o);
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
    void planarPairsAgreeWithTheGeneralPathAcrossManyChunks() {
        // 150 001 poses = three chunks of 65 536 start poses: interpolation, RPE partners and
        // path lengths restart at each chunk boundary
        PlanarTrajectory truth = TestTrajectories.lessonPath(150_001, 0.01);
        LoadedTrajectory r = TestTrajectories.loaded("gt", truth);
        LoadedTrajectory e = TestTrajectories.loaded("est", warped(truth, new Random(7)));
        for (RpeUnit unit : new RpeUnit[] {RpeUnit.SECONDS, RpeUnit.FRAMES}) {
            EvaluationOptions o = EvaluationOptions.preset(Convention.LESSON).withRpe(unit == RpeUnit.SECONDS ? 1 : 50,
                    unit).withPairSelection(PairSelection.ALL_PAIRS).withTOffsetS(0.004);
            assertTrue(ColumnarEvaluator.applies(r, e, o));
            takesColumnarPath(r, e, o);
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

    @Test
    void spatialPairsAgreeWithTheGeneralPathForEveryModelAssociationAndPairRule() {
        Random rnd = new Random(2025);
        int checked = 0;
        for (int trial = 0; trial < 3; trial++) {
            SpatialTrajectory truth = TestTrajectories.helix(250 + 41 * trial, 0.1);
            LoadedTrajectory r = TestTrajectories.loaded("gt", truth);
            LoadedTrajectory e = TestTrajectories.loaded("est", warped3(truth, rnd));
            for (AssociationMethod assoc : new AssociationMethod[] {AssociationMethod.INTERPOLATE,
                AssociationMethod.NEAREST}) {
                for (AlignmentModel model : AlignmentModel.values()) {
                    for (RpeUnit unit : new RpeUnit[] {RpeUnit.SECONDS, RpeUnit.FRAMES}) {
                        for (PairSelection sel : PairSelection.values()) {
                            double delta = unit == RpeUnit.SECONDS ? 0.5 + trial * 0.3 : 1 + trial * 3;
                            EvaluationOptions o = EvaluationOptions.preset(Convention.EVO).withAssociation(assoc)
                                    .withMaxDiffS(0.06).withAlignment(model).withRpe(delta, unit)
                                    .withPairSelection(sel).withTOffsetS(trial * 0.013)
                                    .withNToAlign(trial % 2 == 0 ? -1 : 100);
                            assertTrue(ColumnarEvaluator.applies(r, e, o));
                        takesColumnarPath(r, e, o);
                            String what = assoc + " " + model + " " + unit + " " + sel + " trial " + trial;
                            same(Evaluator.run(r, e, o).report(), Evaluator.evaluate(r, e, o), what);
                            checked++;
                        }
                    }
                }
            }
        }
        assertEquals(3 * 2 * AlignmentModel.values().length * 2 * 2, checked);
    }

    @Test
    void spatialPairsAgreeWithTheGeneralPathAcrossChunksOnEveryThreadCount() throws Exception {
        // 140 001 poses = three chunks of 65 536: interpolation and RPE partners restart at each boundary
        SpatialTrajectory truth = TestTrajectories.helix(140_001, 0.01);
        LoadedTrajectory r = TestTrajectories.loaded("gt", truth);
        LoadedTrajectory e = TestTrajectories.loaded("est", warped3(truth, new Random(5)));
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(2);
        try {
            for (AssociationMethod assoc : new AssociationMethod[] {AssociationMethod.INTERPOLATE,
                AssociationMethod.NEAREST}) {
                EvaluationOptions o = EvaluationOptions.preset(Convention.EVO).withAssociation(assoc)
                        .withMaxDiffS(0.006).withAlignment(AlignmentModel.SE3).withRpe(1, RpeUnit.SECONDS)
                        .withPairSelection(PairSelection.ALL_PAIRS);
                takesColumnarPath(r, e, o);
                EvaluationReport one = Evaluator.evaluate(r, e, o);
                same(Evaluator.run(r, e, o).report(), one, "140 001 poses " + assoc);
                assertEquals(ReportJson.toJson(one), ReportJson.toJson(Evaluator.evaluate(r, e, o,
                        new Parallelism(pool, 3))), assoc + " on 3 threads");
            }
        } finally {
            pool.shutdownNow();
        }
    }

    /** Without this, a fall-back to the general path would make every comparison trivially true. */
    private static void takesColumnarPath(LoadedTrajectory r, LoadedTrajectory e, EvaluationOptions o) {
        assertNotNull(ColumnarEvaluator.evaluate(r.trajectory(), e.trajectory(), o, r.source(), e.source(),
                Parallelism.SEQUENTIAL, false), "the columnar evaluator declined " + o);
    }

    private static void same(EvaluationReport a, EvaluationReport b, String what) {
        assertEquals(a.association().matched(), b.association().matched(), what);
        assertEquals(a.association().dropped(), b.association().dropped(), what);
        assertEquals(a.association().droppedReference(), b.association().droppedReference(), what);
        assertEquals(a.warnings(), b.warnings(), what + " warnings");
        assertEquals(a.coverage(), b.coverage(), what + " coverage");
        close(a.association().maxGapS(), b.association().maxGapS(), what + " max gap");
        close(a.association().interpErrorBoundM(), b.association().interpErrorBoundM(), what + " bound");
        assertEquals(a.alignment().scale(), b.alignment().scale(), what + " scale");
        stats(a.ate().transM(), b.ate().transM(), what + " ATE trans");
        stats(a.ate().rotRad(), b.ate().rotRad(), what + " ATE rot");
        assertEquals(a.rpe().pairs(), b.rpe().pairs(), what + " pairs");
        stats(a.rpe().transM(), b.rpe().transM(), what + " RPE trans");
        stats(a.rpe().rotRad(), b.rpe().rotRad(), what + " RPE rot");
        close(a.rpe().meanHorizonS(), b.rpe().meanHorizonS(), what + " horizon s");
        close(a.rpe().meanHorizonM(), b.rpe().meanHorizonM(), what + " horizon m");
    }

    /** The same errors in the same order: the same bits. */
    private static void stats(EvaluationReport.Stats a, EvaluationReport.Stats b, String what) {
        assertEquals(a, b, what);
    }

    private static void close(Double a, Double b, String what) {
        if (a == null || b == null) {
            assertEquals(a, b, what);
            return;
        }
        assertTrue(Math.abs(a - b) <= Math.max(ABS, REL * Math.abs(a)), what + ": general " + a + " fast " + b);
    }

    /**
     * An SE(3) estimate: the truth moved by a fixed rotation about a tilted axis and a translation,
     * with drift, position noise, a noisy orientation (small random rotation, quaternion not
     * normalised) and the time warp of {@link #warped}.
     */
    static SpatialTrajectory warped3(SpatialTrajectory truth, Random rnd) {
        int n = truth.size();
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] z = new double[n];
        double[] qw = new double[n];
        double[] qx = new double[n];
        double[] qy = new double[n];
        double[] qz = new double[n];
        // fixed rotation: 0.4 rad about the unit axis (0.6, 0, 0.8)
        double h = 0.2;
        double[] g = {Math.cos(h), 0.6 * Math.sin(h), 0, 0.8 * Math.sin(h)};
        double[] rg = new double[9];
        org.trajeval.core.geom.Rotations.fromQuaternion(g[0], g[1], g[2], g[3], rg, 0);
        double[] q = new double[4];
        for (int i = 0; i < n; i++) {
            double s = truth.t(i);
            t[i] = s + 0.01 * Math.sin(0.05 * s) + (i == 0 ? -0.3 : 0.002);
            double px = truth.x(i) + 0.03 * s + 0.05 * rnd.nextGaussian();
            double py = truth.y(i) + 0.05 * rnd.nextGaussian();
            double pz = truth.z(i) + 0.05 * rnd.nextGaussian();
            x[i] = rg[0] * px + rg[1] * py + rg[2] * pz + 3;
            y[i] = rg[3] * px + rg[4] * py + rg[5] * pz - 1;
            z[i] = rg[6] * px + rg[7] * py + rg[8] * pz + 0.5;
            truth.quaternion(i, q);
            double[] noisy = {q[0] + 0.01 * rnd.nextGaussian(), q[1] + 0.01 * rnd.nextGaussian(),
                q[2] + 0.01 * rnd.nextGaussian(), q[3] + 0.01 * rnd.nextGaussian()};
            // g * noisy (Hamilton product), scaled by 1.001: readers keep quaternions as read
            qw[i] = 1.001 * (g[0] * noisy[0] - g[1] * noisy[1] - g[2] * noisy[2] - g[3] * noisy[3]);
            qx[i] = 1.001 * (g[0] * noisy[1] + g[1] * noisy[0] + g[2] * noisy[3] - g[3] * noisy[2]);
            qy[i] = 1.001 * (g[0] * noisy[2] - g[1] * noisy[3] + g[2] * noisy[0] + g[3] * noisy[1]);
            qz[i] = 1.001 * (g[0] * noisy[3] + g[1] * noisy[2] - g[2] * noisy[1] + g[3] * noisy[0]);
        }
        return SpatialTrajectory.of(t, x, y, z, qw, qx, qy, qz);
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
