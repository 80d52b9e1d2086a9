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
 * Alignment recovers a known motion: when the estimate is the truth moved by p -> s R p + t
 * (s = 1 for SE(2)/SE(3)), the fitted alignment (estimate onto reference) is its inverse,
 * p -> (1/s) R^T (p - t), and every error is zero. Seeded random motions and paths.
 */
class AlignmentRecoveryPropertyTest {
    /** Noise-free data: only rounding remains (coordinates of a few 10 m). */
    static final double ROTATION_TOL = 1e-9;
    static final double POSITION_TOL_M = 1e-8;
    static final double SCALE_TOL = 1e-9;

    static long[] seeds() {
        return java.util.stream.LongStream.range(1, 41).toArray();
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void se2AlignmentRecoversAKnownPlanarMotion(long seed) {
        Random rnd = new Random(seed);
        PlanarTrajectory truth = RandomTrajectories.planarPath(rnd, 400, 0.1);
        double theta = (2 * rnd.nextDouble() - 1) * Math.PI;
        double tx = 20 * rnd.nextGaussian();
        double ty = 20 * rnd.nextGaussian();
        PlanarTrajectory est = RandomTrajectories.moved(truth, theta, tx, ty);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                EvaluationOptions.preset(Convention.LESSON).withAlignment(AlignmentModel.SE2));
        // inverse of p -> R(theta) p + t is p -> R(-theta) p - R(-theta) t
        double c = Math.cos(-theta);
        double s = Math.sin(-theta);
        double[][] rot = r.alignment().rotation();
        assertEquals(c, rot[0][0], ROTATION_TOL);
        assertEquals(-s, rot[0][1], ROTATION_TOL);
        assertEquals(s, rot[1][0], ROTATION_TOL);
        assertEquals(-(c * tx - s * ty), r.alignment().translationM()[0], POSITION_TOL_M);
        assertEquals(-(s * tx + c * ty), r.alignment().translationM()[1], POSITION_TOL_M);
        assertEquals(0.0, r.ate().transM().max(), POSITION_TOL_M);
        assertEquals(0.0, r.ate().rotRad().max(), ROTATION_TOL);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void se3AlignmentRecoversAKnownRigidMotion(long seed) {
        recovers(seed, AlignmentModel.SE3, 1.0);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void sim3AlignmentRecoversAKnownSimilarity(long seed) {
        recovers(seed, AlignmentModel.SIM3, 0.2 + 3 * new Random(-seed).nextDouble());
    }

    private static void recovers(long seed, AlignmentModel model, double scale) {
        Random rnd = new Random(seed);
        SpatialTrajectory truth = RandomTrajectories.spatialPath(rnd, 400, 0.1, 0.0);
        double[] q = RandomTrajectories.randomQuaternion(rnd);
        double[] t = {20 * rnd.nextGaussian(), 20 * rnd.nextGaussian(), 5 * rnd.nextGaussian()};
        SpatialTrajectory est = RandomTrajectories.moved(truth, q, t, scale);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                EvaluationOptions.preset(Convention.LESSON, false).withAlignment(model));
        double[][] m = RandomTrajectories.matrix(q);
        double[][] rot = r.alignment().rotation();
        for (int i = 0; i < 3; i++) {
            double expectedT = 0;
            for (int j = 0; j < 3; j++) {
                assertEquals(m[j][i], rot[i][j], ROTATION_TOL, "R^T entry " + i + "," + j);
                expectedT -= m[j][i] * t[j] / scale;
            }
            assertEquals(expectedT, r.alignment().translationM()[i], POSITION_TOL_M, "translation " + i);
        }
        assertEquals(1.0 / scale, r.alignment().scale(), SCALE_TOL);
        assertEquals(0.0, r.ate().transM().max(), POSITION_TOL_M);
        assertEquals(0.0, r.ate().rotRad().max(), 1e-7);
    }
}
