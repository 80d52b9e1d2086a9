package org.trajeval.core.property;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.trajeval.core.property.RandomTrajectories.loaded;

import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Invariances that follow from the definitions: ATE after a rigid alignment does not depend on
 * where the estimate was put (the alignment absorbs any rigid motion of it); RPE compares
 * relative motions T_i^-1 T_j, which a rigid motion M of a whole trajectory leaves unchanged
 * ((M T_i)^-1 (M T_j) = T_i^-1 T_j), whichever of the two trajectories is moved.
 */
class InvariancePropertyTest {
    /** Same statistics up to rounding (relative, or absolute near zero in m and rad). */
    static final double REL_TOL = 1e-9;
    static final double ABS_TOL = 1e-10;

    static long[] seeds() {
        return java.util.stream.LongStream.range(1, 31).toArray();
    }

    /** A planar pair: noisy estimate on stamps shifted by 0.03 s, so association interpolates. */
    private static PlanarTrajectory[] planarPair(Random rnd) {
        PlanarTrajectory truth = RandomTrajectories.planarPath(rnd, 500, 0.1);
        PlanarTrajectory noisy = RandomTrajectories.noisy(rnd, truth, 0.05);
        double[] t = truth.timestamps().clone();
        for (int i = 0; i < t.length; i++) {
            t[i] += 0.03;
        }
        PlanarTrajectory est = PlanarTrajectory.of(t, noisy.xs().clone(), noisy.ys().clone(), yaws(noisy));
        return new PlanarTrajectory[] {truth, est};
    }

    private static double[] yaws(PlanarTrajectory a) {
        double[] yaw = new double[a.size()];
        for (int i = 0; i < yaw.length; i++) {
            yaw[i] = a.yaw(i);
        }
        return yaw;
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void planarAteAfterSe2AlignmentIgnoresARigidMotionOfTheEstimate(long seed) {
        Random rnd = new Random(seed);
        PlanarTrajectory[] p = planarPair(rnd);
        PlanarTrajectory movedEst = RandomTrajectories.moved(p[1], (2 * rnd.nextDouble() - 1) * Math.PI,
                30 * rnd.nextGaussian(), 30 * rnd.nextGaussian());
        EvaluationOptions o = EvaluationOptions.preset(Convention.LESSON).withAlignment(AlignmentModel.SE2);
        EvaluationReport a = Evaluator.evaluate(loaded("gt", p[0]), loaded("est", p[1]), o);
        EvaluationReport b = Evaluator.evaluate(loaded("gt", p[0]), loaded("est", movedEst), o);
        sameStats(a.ate().transM(), b.ate().transM());
        sameStats(a.ate().rotRad(), b.ate().rotRad());
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void spatialAteAfterSe3AlignmentIgnoresARigidMotionOfTheEstimate(long seed) {
        Random rnd = new Random(seed);
        SpatialTrajectory truth = RandomTrajectories.spatialPath(rnd, 500, 0.1, 0.0);
        SpatialTrajectory est = RandomTrajectories.spatialPath(new Random(seed), 500, 0.1, 0.03);
        SpatialTrajectory movedEst = RandomTrajectories.moved(est, RandomTrajectories.randomQuaternion(rnd),
                new double[] {10 * rnd.nextGaussian(), 10 * rnd.nextGaussian(), 10 * rnd.nextGaussian()}, 1.0);
        EvaluationOptions o = EvaluationOptions.preset(Convention.LESSON, false).withAlignment(AlignmentModel.SE3);
        EvaluationReport a = Evaluator.evaluate(loaded("gt", truth), loaded("est", est), o);
        EvaluationReport b = Evaluator.evaluate(loaded("gt", truth), loaded("est", movedEst), o);
        sameStats(a.ate().transM(), b.ate().transM());
        sameStats(a.ate().rotRad(), b.ate().rotRad());
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void planarRpeIgnoresARigidMotionOfEitherWholeTrajectory(long seed) {
        Random rnd = new Random(seed);
        PlanarTrajectory[] p = planarPair(rnd);
        double theta = (2 * rnd.nextDouble() - 1) * Math.PI;
        PlanarTrajectory movedRef = RandomTrajectories.moved(p[0], theta, 30 * rnd.nextGaussian(), 30 * rnd.nextGaussian());
        PlanarTrajectory movedEst = RandomTrajectories.moved(p[1], -2 * theta, 30 * rnd.nextGaussian(), 5.0);
        for (AlignmentModel model : new AlignmentModel[] {AlignmentModel.NONE, AlignmentModel.SE2}) {
            EvaluationOptions o = EvaluationOptions.preset(Convention.LESSON).withAlignment(model);
            EvaluationReport a = Evaluator.evaluate(loaded("gt", p[0]), loaded("est", p[1]), o);
            EvaluationReport byRef = Evaluator.evaluate(loaded("gt", movedRef), loaded("est", p[1]), o);
            EvaluationReport byEst = Evaluator.evaluate(loaded("gt", p[0]), loaded("est", movedEst), o);
            for (EvaluationReport b : new EvaluationReport[] {byRef, byEst}) {
                assertEquals(a.rpe().pairs(), b.rpe().pairs());
                sameStats(a.rpe().transM(), b.rpe().transM());
                sameStats(a.rpe().rotRad(), b.rpe().rotRad());
            }
        }
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void spatialRpeIgnoresARigidMotionOfEitherWholeTrajectory(long seed) {
        Random rnd = new Random(seed);
        SpatialTrajectory truth = RandomTrajectories.spatialPath(rnd, 500, 0.1, 0.0);
        SpatialTrajectory est = RandomTrajectories.spatialPath(new Random(seed), 500, 0.1, 0.03);
        SpatialTrajectory movedRef = RandomTrajectories.moved(truth, RandomTrajectories.randomQuaternion(rnd),
                new double[] {10 * rnd.nextGaussian(), 1, -3}, 1.0);
        SpatialTrajectory movedEst = RandomTrajectories.moved(est, RandomTrajectories.randomQuaternion(rnd),
                new double[] {-4, 10 * rnd.nextGaussian(), 2}, 1.0);
        for (Convention c : new Convention[] {Convention.LESSON, Convention.EVO}) {
            EvaluationOptions o = EvaluationOptions.preset(c, false).withAlignment(AlignmentModel.NONE);
            EvaluationReport a = Evaluator.evaluate(loaded("gt", truth), loaded("est", est), o);
            EvaluationReport byRef = Evaluator.evaluate(loaded("gt", movedRef), loaded("est", est), o);
            EvaluationReport byEst = Evaluator.evaluate(loaded("gt", truth), loaded("est", movedEst), o);
            for (EvaluationReport b : new EvaluationReport[] {byRef, byEst}) {
                assertEquals(a.rpe().pairs(), b.rpe().pairs());
                sameStats(a.rpe().transM(), b.rpe().transM());
                sameStats(a.rpe().rotRad(), b.rpe().rotRad());
            }
        }
    }

    static void sameStats(EvaluationReport.Stats a, EvaluationReport.Stats b) {
        assertEquals(a.n(), b.n(), "n");
        close("rmse", a.rmse(), b.rmse());
        close("mean", a.mean(), b.mean());
        close("median", a.median(), b.median());
        close("std", a.std(), b.std());
        close("min", a.min(), b.min());
        close("max", a.max(), b.max());
    }

    private static void close(String what, double a, double b) {
        assertEquals(a, b, Math.max(ABS_TOL, REL_TOL * Math.max(Math.abs(a), Math.abs(b))), what);
    }
}
