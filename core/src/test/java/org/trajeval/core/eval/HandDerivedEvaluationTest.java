package org.trajeval.core.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.trajeval.core.eval.TestTrajectories.lessonPath;
import static org.trajeval.core.eval.TestTrajectories.loaded;
import static org.trajeval.core.eval.TestTrajectories.moved;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.property.RandomTrajectories;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;

/** Cases whose answers are derived by hand in the comments. */
class HandDerivedEvaluationTest {
    static final double POSITION_TOL_M = 1e-9;
    static final double ANGLE_TOL_RAD = 1e-9;

    private static EvaluationOptions lesson() {
        return EvaluationOptions.preset(Convention.LESSON);
    }

    @Test
    void rigidMotionOfTheEstimateGivesZeroAteAfterSe2AlignmentIncludingYaw() {
        // the estimate is the truth turned by 0.7 rad and shifted by (5, -3) m: se2 alignment undoes
        // it exactly, so every translation and yaw error is 0 by construction
        PlanarTrajectory truth = lessonPath(300, 0.1);
        PlanarTrajectory est = moved(truth, 0.7, 5.0, -3.0);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est), lesson());
        assertEquals(0.0, r.ate().transM().rmse(), POSITION_TOL_M);
        assertEquals(0.0, r.ate().rotRad().rmse(), ANGLE_TOL_RAD);
        assertEquals(0.0, r.rpe().transM().rmse(), POSITION_TOL_M);
        assertEquals(-0.7, Math.atan2(r.alignment().rotation()[1][0], r.alignment().rotation()[0][0]), 1e-12);
    }

    @Test
    void rigidMotionOfA3dEstimateGivesZeroAteAfterSe3Alignment() {
        // the helix moved by a rotation about a tilted axis and a translation: se3 recovers it
        SpatialTrajectory truth = TestTrajectories.helix(400, 0.05);
        double[] q = {Math.cos(0.4), Math.sin(0.4) * 0.6, Math.sin(0.4) * 0.0, Math.sin(0.4) * 0.8};
        SpatialTrajectory est = RandomTrajectories.moved(truth, q, new double[] {1.0, -2.0, 0.5}, 1.0);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                EvaluationOptions.preset(Convention.LESSON, false));
        assertEquals(0.0, r.ate().transM().max(), 1e-8);
        assertEquals(0.0, r.ate().rotRad().max(), 1e-7);
    }

    @Test
    void sim3AlignmentRecoversScale() {
        // a monocular-like estimate at 0.5 x scale: sim3 finds scale 2 and zero error
        SpatialTrajectory truth = TestTrajectories.helix(400, 0.05);
        double[] q = {1, 0, 0, 0};
        SpatialTrajectory est = RandomTrajectories.moved(truth, q, new double[] {0.3, 0.1, 0}, 0.5);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                EvaluationOptions.preset(Convention.EVO).withAlignment(AlignmentModel.SIM3));
        assertEquals(2.0, r.alignment().scale(), 1e-12);
        assertEquals(0.0, r.ate().transM().max(), 1e-9);
    }

    @Test
    void uniformOffsetGivesAteEqualToTheOffsetWithoutAlignment() {
        // every estimated pose is 0.10 m to the left (+y) of the truth: ATE-RMSE = 0.10 m by hand,
        // and since all relative motions agree, RPE = 0
        PlanarTrajectory truth = lessonPath(200, 0.1);
        PlanarTrajectory est = moved(truth, 0.0, 0.0, 0.10);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                lesson().withAlignment(AlignmentModel.NONE));
        assertEquals(0.10, r.ate().transM().rmse(), POSITION_TOL_M);
        assertEquals(0.10, r.ate().transM().min(), POSITION_TOL_M);
        assertEquals(0.0, r.ate().transM().std(), POSITION_TOL_M);
        assertEquals(0.0, r.rpe().transM().rmse(), POSITION_TOL_M);
    }

    @Test
    void yawErrorsWrapAcrossPlusMinusPiManyTimes() {
        // the truth spins 20 full turns; the estimate's yaw is the truth's + 0.05 rad + 2 pi k with
        // k changing every pose (written unwrapped, e.g. 40 pi + ...): every yaw error is 0.05 rad
        int n = 400;
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yawTruth = new double[n];
        double[] yawEst = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = i * 0.1;
            x[i] = Math.cos(i * 0.3);
            y[i] = Math.sin(i * 0.3);
            yawTruth[i] = Angles2.wrapForTest(i * 2 * Math.PI * 20 / n);
            yawEst[i] = yawTruth[i] + 0.05 + 2 * Math.PI * ((i % 7) - 3);
        }
        PlanarTrajectory truth = PlanarTrajectory.of(t, x, y, yawTruth);
        PlanarTrajectory est = PlanarTrajectory.of(t.clone(), x.clone(), y.clone(), yawEst);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                lesson().withAlignment(AlignmentModel.NONE));
        assertEquals(0.05, r.ate().rotRad().min(), 1e-9);
        assertEquals(0.05, r.ate().rotRad().max(), 1e-9);
    }

    @Test
    void lessonRpeExampleByHand() {
        // Q_i = I, Q_j = (1 m, 0, 0 rad); P_i = I, P_j = (1.1 m, 0.1 m, 0.05 rad), 1 s apart.
        // E = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j) = (0.1 m, 0.1 m, 0.05 rad): |trans E| = sqrt(0.02) m,
        // rotation 0.05 rad.
        double[] t = {0.0, 1.0};
        PlanarTrajectory truth = PlanarTrajectory.of(t, new double[] {0, 1}, new double[] {0, 0}, new double[] {0, 0});
        PlanarTrajectory est = PlanarTrajectory.of(t.clone(), new double[] {0, 1.1}, new double[] {0, 0.1},
                new double[] {0, 0.05});
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                lesson().withAlignment(AlignmentModel.NONE));
        assertEquals(1, r.rpe().pairs());
        assertEquals(Math.sqrt(0.02), r.rpe().transM().rmse(), 1e-12);
        assertEquals(0.05, r.rpe().rotRad().rmse(), 1e-12);
    }

    @Test
    void lessonRpePairsEveryStartPoseWithTheFirstSampleAtOrAfterDelta() {
        // stamps 0, 0.4, 0.8, 1.0, 1.3, 2.5 s, delta 1 s: i=0 -> 1.0 (index 3), i=1 (0.4) -> 1.4 -> 2.5
        // (index 5), i=2 (0.8) -> 1.8 -> index 5, i=3 (1.0) -> 2.0 -> index 5, i=4 (1.3) -> 2.3 ->
        // index 5, i=5 -> none: 5 pairs, mean horizon (1.0 + 2.1 + 1.7 + 1.5 + 1.2) / 5 = 1.5 s
        double[] t = {0.0, 0.4, 0.8, 1.0, 1.3, 2.5};
        double[] x = {0, 1, 2, 3, 4, 5};
        double[] zero = new double[6];
        PlanarTrajectory truth = PlanarTrajectory.of(t, x, zero, zero.clone());
        PlanarTrajectory est = PlanarTrajectory.of(t.clone(), x.clone(), zero.clone(), zero.clone());
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                lesson().withAlignment(AlignmentModel.NONE));
        assertEquals(5, r.rpe().pairs());
        assertEquals(1.5, r.rpe().meanHorizonS(), 1e-12);
        EvaluationReport chained = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                lesson().withAlignment(AlignmentModel.NONE).withPairSelection(PairSelection.CONSECUTIVE));
        // consecutive: 0 -> 3 (1.0 s), 3 -> 5 (2.5 s >= 2.0): 2 pairs
        assertEquals(2, chained.rpe().pairs());
    }

    @Test
    void interpolationIsExactOnLinearMotionAndCropsPosesOutsideTheReference() {
        // reference moves at 2 m/s along x sampled every 0.1 s on [0, 10] s; estimate samples the
        // same motion at odd times, 3 of them outside [0, 10] s: they are dropped (crop), the others
        // match exactly (linear interpolation of linear motion), ATE = 0
        int n = 101;
        double[] t = new double[n];
        double[] x = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = i * 0.1;
            x[i] = 2.0 * t[i];
        }
        double[] te = {-0.5, -0.01, 0.033, 1.777, 5.5, 9.999, 10.2};
        double[] xe = new double[te.length];
        for (int i = 0; i < te.length; i++) {
            xe[i] = 2.0 * te[i];
        }
        PlanarTrajectory truth = PlanarTrajectory.of(t, x, new double[n], new double[n]);
        PlanarTrajectory est = PlanarTrajectory.of(te, xe, new double[te.length], new double[te.length]);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                lesson().withAlignment(AlignmentModel.NONE));
        assertEquals(4, r.association().matched());
        assertEquals(3, r.association().dropped());
        assertEquals(0.0, r.ate().transM().max(), 1e-12);
        // h = 0.1 s and A_max = 0 (linear motion): the Proposition 2 bound is 0 m
        assertEquals(0.1, r.association().maxGapS(), 1e-12);
        assertEquals(0.0, r.association().interpErrorBoundM(), 1e-9);
        InputException e = assertThrows(InputException.class, () -> Evaluator.evaluate(loaded("gt", truth),
                loaded("est", est), lesson().withAlignment(AlignmentModel.NONE).withOverlap(OverlapPolicy.STRICT)));
        assertEquals(InputProblem.OUTSIDE_OVERLAP, e.problem());
    }

    @Test
    void nearestAssociationTakesTheEarlierStampOnTiesAndIsInclusive() {
        // reference stamps 0.00, 0.02 s; estimate stamp 0.01 s: both 0.01 s away (max diff 0.01 s,
        // inclusive): evo's rule takes the earlier, so the estimate pairs with x = 0 (error 0.5 m)
        // rather than x = 1 (error 0.5 m too, but distinguishable through y).
        PlanarTrajectory truth = PlanarTrajectory.of(new double[] {0.0, 0.02, 0.5},
                new double[] {0, 1, 2}, new double[] {0, 5, 9}, new double[3]);
        PlanarTrajectory est = PlanarTrajectory.of(new double[] {0.01, 0.5},
                new double[] {0, 2}, new double[] {0, 9}, new double[2]);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                EvaluationOptions.preset(Convention.EVO).withMaxDiffS(0.01));
        assertEquals(2, r.association().matched());
        // pair 1: (0,0) vs (0,0): 0 m; pair 2: 0 m. Had the later stamp won, pair 1 would be 5.1 m off.
        assertEquals(0.0, r.ate().transM().max(), 1e-12);
    }

    @Test
    void noOverlapIsRefusedNamingTheSpans() {
        PlanarTrajectory truth = lessonPath(50, 0.1);
        PlanarTrajectory est = PlanarTrajectory.of(new double[] {100, 101}, new double[2], new double[2],
                new double[2]);
        InputException e = assertThrows(InputException.class,
                () -> Evaluator.evaluate(loaded("gt.csv", truth), loaded("est.csv", est), lesson()));
        assertEquals(InputProblem.NO_OVERLAP, e.problem());
        assertEquals("est.csv", e.source());
    }

    @Test
    void collinearPointsMakeSe3AlignmentDegenerate() {
        // all positions on the x axis: the covariance has rank 1 < 2, rotation about x is free
        int n = 20;
        double[] t = new double[n];
        double[] x = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = i;
            x[i] = i;
        }
        PlanarTrajectory line = PlanarTrajectory.of(t, x, new double[n], new double[n]);
        InputException e = assertThrows(InputException.class, () -> Evaluator.evaluate(loaded("gt", line),
                loaded("est", line), EvaluationOptions.preset(Convention.EVO).withAlignment(AlignmentModel.SE3)));
        assertEquals(InputProblem.DEGENERATE_ALIGNMENT, e.problem());
    }

    @Test
    void rpeIsInvariantUnderARigidMotionOfTheWholeEstimate() {
        // seeded property: a random rigid motion of the estimate changes no relative motion
        Random rnd = new Random(42);
        PlanarTrajectory truth = lessonPath(300, 0.1);
        PlanarTrajectory noisy = noisy(truth, rnd);
        EvaluationOptions o = lesson().withAlignment(AlignmentModel.NONE);
        EvaluationReport base = Evaluator.evaluate(loaded("gt", truth), loaded("est", noisy), o);
        for (int k = 0; k < 20; k++) {
            PlanarTrajectory m = moved(noisy, rnd.nextDouble() * 20 - 10, rnd.nextGaussian() * 50,
                    rnd.nextGaussian() * 50);
            EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", m), o);
            assertEquals(base.rpe().transM().rmse(), r.rpe().transM().rmse(), 1e-9);
            assertEquals(base.rpe().rotRad().rmse(), r.rpe().rotRad().rmse(), 1e-9);
            EvaluationReport aligned = Evaluator.evaluate(loaded("gt", truth), loaded("est", m), lesson());
            EvaluationReport alignedBase = Evaluator.evaluate(loaded("gt", truth), loaded("est", noisy), lesson());
            assertEquals(alignedBase.ate().transM().rmse(), aligned.ate().transM().rmse(), 1e-9);
        }
    }

    @Test
    void driftOfAStraightPathWithOnePercentScaleErrorIsOnePercent() {
        // truth: 2000 m straight at 1 m per frame; estimate: the same at 1.01 m per frame. A segment
        // of length L ends at the first frame whose distance exceeds L, i.e. L + 1 frames (m) later,
        // where the estimate is 0.01 (L + 1) m off: error / L = 0.01 (L + 1) / L, averaged over all
        // segments of lengths 100..800 m starting every 10 frames; rotation error 0.
        int n = 2001;
        double[] t = new double[n];
        double[] x = new double[n];
        double[] xe = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = i;
            x[i] = i;
            xe[i] = 1.01 * i;
        }
        PlanarTrajectory truth = PlanarTrajectory.of(t, x, new double[n], new double[n]);
        PlanarTrajectory est = PlanarTrajectory.of(t.clone(), xe, new double[n], new double[n]);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                EvaluationOptions.preset(Convention.KITTI));
        double expected = 0;
        int count = 0;
        for (int li = 1; li <= 8; li++) {
            double len = 100.0 * li;
            // starts every 10 frames whose end (start + len + 1) is inside the path
            for (int f = 0; f < n; f += 10) {
                if (f + len + 1 < n) {
                    expected += 0.01 * (len + 1) / len;
                    count++;
                }
            }
        }
        assertEquals(count, r.drift().segments());
        assertEquals(100.0 * expected / count, r.drift().transPct(), 1e-9);
        assertEquals(0.0, r.drift().rotDegPerM(), 1e-12);
    }

    @Test
    void associationWithAnOffsetShiftsTheEstimateClock() {
        // the estimate's clock runs 0.5 s behind: --t-offset 0.5 s realigns it exactly
        PlanarTrajectory truth = lessonPath(200, 0.1);
        double[] t = truth.timestamps();
        for (int i = 0; i < t.length; i++) {
            t[i] -= 0.5;
        }
        PlanarTrajectory est = PlanarTrajectory.of(t, truth.xs(), truth.ys(), truth.yaws());
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est), EvaluationOptions
                .preset(Convention.EVO).withTOffsetS(0.5).withAssociation(AssociationMethod.NEAREST)
                .withRpe(1, RpeUnit.FRAMES));
        assertEquals(200, r.association().matched());
        assertEquals(0.0, r.ate().transM().max(), 1e-12);
    }

    private static PlanarTrajectory noisy(PlanarTrajectory a, Random rnd) {
        int n = a.size();
        double[] x = a.xs();
        double[] y = a.ys();
        double[] yaw = a.yaws();
        for (int i = 0; i < n; i++) {
            x[i] += 0.05 * rnd.nextGaussian() + 0.01 * i * 0.1;
            y[i] += 0.05 * rnd.nextGaussian();
            yaw[i] += 0.02 * rnd.nextGaussian();
        }
        return PlanarTrajectory.of(a.timestamps(), x, y, yaw);
    }
}
