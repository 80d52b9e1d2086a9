package org.trajeval.core.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;
import java.util.Random;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.trajeval.core.align.Alignment;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.AssociationOptions;
import org.trajeval.core.assoc.InterpolatedReference;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.assoc.TimeAssociation;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * The planar kernels ({@link PlanarErrors}) must give the 3x3 matrix kernels' per-pose ATE and
 * per-pair RPE errors bit for bit ({@link Double#doubleToRawLongBits}): seeded random planar pairs
 * with yaws near 0 and +-pi and wrapping over many turns, tiny, ordinary, huge and overflowing
 * coordinates, every alignment model, interpolated and nearest association, and the pairs of every
 * RPE rule (frames and seconds, every start and consecutive), with windows restarted as at chunk
 * boundaries and pairs further apart than the window's first capacity; the ATE both before the
 * RPE and after it, when the windows have kept every pose's ATE rotation error.
 */
class PlanarErrorsTest {
    /** The models whose transform on planar data is a rotation about +z: the planar kernels must take them. */
    private static final Set<AlignmentModel> ABOUT_Z = EnumSet.of(AlignmentModel.NONE, AlignmentModel.SE2,
            AlignmentModel.SIM2, AlignmentModel.POSYAW, AlignmentModel.ORIGIN);

    @Test
    void planarKernelsGiveTheMatrixKernelsErrorsBitForBit() {
        Random rnd = new Random(1515);
        int planarRuns = 0;
        for (int trial = 0; trial < 8; trial++) {
            double size = new double[] {1e-9, 1.0, 1e3, 1e12, 1.0, 1e-3, 1e150, 1e305}[trial];
            int n = 2500 + 97 * trial;
            PlanarTrajectory ref = randomPath(rnd, n, size, trial);
            PlanarTrajectory est = estimateOf(rnd, ref, size, trial);
            for (AssociationMethod assoc : new AssociationMethod[] {AssociationMethod.INTERPOLATE,
                AssociationMethod.NEAREST}) {
                for (AlignmentModel model : AlignmentModel.values()) {
                    AssociatedColumns fast = associate(ref, est, assoc);
                    AssociatedColumns matrix = associate(ref, est, assoc);
                    AlignmentTransform tf;
                    try {
                        tf = Alignment.fit(model, fast, -1, "est");
                    } catch (RuntimeException degenerate) {
                        continue; // se3 on overflowing coordinates: the evaluator refuses it too
                    }
                    fast.align(tf);
                    matrix.alignForMatrixKernels(tf);
                    String what = "trial " + trial + " " + assoc + " " + model;
                    if (ABOUT_Z.contains(model) && size < 1e300) {
                        assertTrue(fast.planarKernels(), what + " should take the planar kernels");
                    }
                    planarRuns += fast.planarKernels() ? 1 : 0;
                    sameAte(fast, matrix, what);
                    samePairs(fast, matrix, what);
                    sameAte(fast, matrix, what + " after the RPE windows");
                }
            }
        }
        assertTrue(planarRuns >= 8 * 2 * ABOUT_Z.size() - 2 * ABOUT_Z.size(), "planar runs " + planarRuns);
    }

    @Test
    void evaluatorReportsOnOneAndTwoThreadsEqualTheGeneralPathOnHardPlanarData() throws Exception {
        // 140 001 poses: three chunks; yaws near +-pi and wrapping; the RPE spans 2000 frames, more
        // than the window's first capacity
        Random rnd = new Random(77);
        PlanarTrajectory ref = randomPath(rnd, 140_001, 1.0, 3);
        PlanarTrajectory est = estimateOf(rnd, ref, 1.0, 3);
        LoadedTrajectory r = TestTrajectories.loaded("gt", ref);
        LoadedTrajectory e = TestTrajectories.loaded("est", est);
        java.util.concurrent.ExecutorService pool = java.util.concurrent.Executors.newFixedThreadPool(2);
        try {
            for (AssociationMethod assoc : new AssociationMethod[] {AssociationMethod.INTERPOLATE,
                AssociationMethod.NEAREST}) {
                for (AlignmentModel model : new AlignmentModel[] {AlignmentModel.SE2, AlignmentModel.POSYAW}) {
                    EvaluationOptions o = EvaluationOptions.preset(Convention.LESSON).withAssociation(assoc)
                            .withMaxDiffS(0.02).withAlignment(model).withRpe(2000, RpeUnit.FRAMES)
                            .withPairSelection(PairSelection.ALL_PAIRS);
                    String what = assoc + " " + model;
                    String one = ReportJson.toJson(Evaluator.evaluate(r, e, o));
                    assertEquals(one, ReportJson.toJson(Evaluator.evaluate(r, e, o, new Parallelism(pool, 2))),
                            what + " on 2 threads");
                    var general = Evaluator.run(r, e, o).report();
                    var fast = Evaluator.evaluate(r, e, o);
                    assertEquals(general.ate().transM(), fast.ate().transM(), what + " ATE trans");
                    assertEquals(general.ate().rotRad(), fast.ate().rotRad(), what + " ATE rot");
                    assertEquals(general.rpe().transM(), fast.rpe().transM(), what + " RPE trans");
                    assertEquals(general.rpe().rotRad(), fast.rpe().rotRad(), what + " RPE rot");
                }
            }
        } finally {
            pool.shutdownNow();
        }
    }

    private static AssociatedColumns associate(PlanarTrajectory ref, PlanarTrajectory est, AssociationMethod assoc) {
        if (assoc == AssociationMethod.INTERPOLATE) {
            int m = est.size();
            InterpolatedReference interp = InterpolatedReference.planar(ref, m);
            interp.fill(est::t, 0, m);
            return AssociatedColumns.interpolated(ref, est, interp, 0, m, 0.0);
        }
        TimeAssociation.NearestPairs np = TimeAssociation.nearestPairs(ref, est,
                new AssociationOptions(AssociationMethod.NEAREST, 0.02, 0.0, OverlapPolicy.CROP), "gt", "est");
        return AssociatedColumns.matched(ref, est, np.reference(), np.estimate(), np.count(), 0.0,
                Parallelism.SEQUENTIAL);
    }

    private static void sameAte(AssociatedColumns fast, AssociatedColumns matrix, String what) {
        AssociatedColumns.Scratch a = new AssociatedColumns.Scratch();
        AssociatedColumns.Scratch b = new AssociatedColumns.Scratch();
        for (int k = 0; k < fast.size(); k++) {
            fast.ate(k, a);
            matrix.ate(k, b);
            same(b, a, what + " ATE pose " + k);
        }
    }

    /** The pairs of every rule: (i, i + d) from every start and consecutively, and t_j &gt;= t_i + delta. */
    private static void samePairs(AssociatedColumns fast, AssociatedColumns matrix, String what) {
        int m = fast.size();
        AssociatedColumns.Scratch b = new AssociatedColumns.Scratch();
        for (int d : new int[] {1, 7, 1500}) {
            AssociatedColumns.Scratch a = new AssociatedColumns.Scratch();
            for (int i = 0; i + d < m; i++) {
                if (i % 1000 == 0) {
                    a = new AssociatedColumns.Scratch(); // a new chunk: a new window
                }
                compare(fast, matrix, i, i + d, a, b, what + " frames " + d);
            }
            a = new AssociatedColumns.Scratch();
            for (int i = 0; i + d < m; i += d) {
                compare(fast, matrix, i, i + d, a, b, what + " consecutive frames " + d);
            }
        }
        for (double delta : new double[] {0.05, 1.0, 40.0}) {
            AssociatedColumns.Scratch a = new AssociatedColumns.Scratch();
            int j = 0;
            for (int i = 0; i < m; i++) {
                j = Math.max(j, i);
                while (j < m && fast.stamp(j) < fast.stamp(i) + delta) {
                    j++;
                }
                if (j >= m) {
                    break;
                }
                compare(fast, matrix, i, j, a, b, what + " seconds " + delta);
            }
        }
    }

    private static void compare(AssociatedColumns fast, AssociatedColumns matrix, int i, int j,
            AssociatedColumns.Scratch a, AssociatedColumns.Scratch b, String what) {
        fast.rpe(i, j, a);
        matrix.rpe(i, j, b);
        same(b, a, what + " pair " + i + " " + j);
    }

    private static void same(AssociatedColumns.Scratch expected, AssociatedColumns.Scratch actual, String what) {
        if (Double.doubleToRawLongBits(expected.transError) != Double.doubleToRawLongBits(actual.transError)
                || Double.doubleToRawLongBits(expected.rotError) != Double.doubleToRawLongBits(actual.rotError)) {
            assertEquals(expected.transError + " m " + expected.rotError + " rad",
                    actual.transError + " m " + actual.rotError + " rad", what);
        }
    }

    /**
     * A random planar reference: stamps 0.01 s apart with jitter, positions a random walk of step
     * {@code size} (m), yaw by kind: 0 a random walk wrapping over many turns, 1 near 0, 2 near +-pi
     * (either side of the cut), 3 a mix with jumps of whole turns.
     */
    static PlanarTrajectory randomPath(Random rnd, int n, double size, int trial) {
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        double tt = 0;
        double px = 0;
        double py = 0;
        double h = 0;
        for (int i = 0; i < n; i++) {
            tt += 0.01 * (0.5 + rnd.nextDouble());
            px += size * rnd.nextGaussian();
            py += size * rnd.nextGaussian();
            switch (trial % 4) {
                case 0 -> h += 0.3 * rnd.nextGaussian();
                case 1 -> h = 1e-4 * rnd.nextGaussian();
                case 2 -> h = (rnd.nextBoolean() ? Math.PI : -Math.PI) + 1e-6 * rnd.nextGaussian();
                default -> h = rnd.nextGaussian() + 2 * Math.PI * (rnd.nextInt(41) - 20);
            }
            t[i] = tt;
            x[i] = px;
            y[i] = py;
            yaw[i] = h;
        }
        return PlanarTrajectory.of(t, x, y, yaw);
    }

    /**
     * An estimate of the reference: stamps shifted inside its span, positions rotated by 0.4 rad,
     * offset and noisy, yaws noisy and some a whole turn off.
     */
    static PlanarTrajectory estimateOf(Random rnd, PlanarTrajectory ref, double size, int trial) {
        int n = ref.size() - 2;
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        double c = Math.cos(0.4);
        double s = Math.sin(0.4);
        for (int i = 0; i < n; i++) {
            int k = i + 1;
            t[i] = ref.t(k) + 0.003 * (ref.t(k + 1) - ref.t(k));
            x[i] = c * ref.x(k) - s * ref.y(k) + 3 * size + 0.1 * size * rnd.nextGaussian();
            y[i] = s * ref.x(k) + c * ref.y(k) - size + 0.1 * size * rnd.nextGaussian();
            yaw[i] = ref.yaw(k) + 0.4 + (trial % 4 == 1 ? 1e-5 : 0.02) * rnd.nextGaussian()
                    + 2 * Math.PI * (i % 3 - 1);
        }
        return PlanarTrajectory.of(t, x, y, yaw);
    }
}
