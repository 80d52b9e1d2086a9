package org.trajeval.core.property;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.trajeval.core.property.RandomTrajectories.loaded;

import java.util.Random;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Time association: linear interpolation reproduces linear motion exactly (at any query stamp,
 * on irregular reference stamps), and the crop and strict overlap policies give the same result
 * when every estimate stamp lies inside the reference's span.
 */
class AssociationPropertyTest {
    /** Linear interpolation of values up to ~100 m: only rounding (a few ulp) remains. */
    static final double POSITION_TOL_M = 1e-10;
    static final double ANGLE_TOL_RAD = 1e-12;

    static long[] seeds() {
        return java.util.stream.LongStream.range(1, 31).toArray();
    }

    /** Sorted random stamps in [t0, t0 + n * meanGap], strictly increasing. */
    private static double[] stamps(Random rnd, int n, double t0, double meanGap) {
        double[] t = new double[n];
        double s = t0;
        for (int i = 0; i < n; i++) {
            s += meanGap * (0.1 + 1.8 * rnd.nextDouble());
            t[i] = s;
        }
        return t;
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void interpolationIsExactOnLinearPlanarMotion(long seed) {
        Random rnd = new Random(seed);
        double x0 = 10 * rnd.nextGaussian();
        double vx = rnd.nextGaussian();
        double y0 = 10 * rnd.nextGaussian();
        double vy = rnd.nextGaussian();
        double yaw = (2 * rnd.nextDouble() - 1) * Math.PI;
        double[] tr = stamps(rnd, 300, 5.0, 0.2);
        double[] te = inside(rnd, 200, tr[0], tr[tr.length - 1]);
        PlanarTrajectory ref = linearPlanar(tr, x0, vx, y0, vy, yaw);
        PlanarTrajectory est = linearPlanar(te, x0, vx, y0, vy, yaw);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", ref), loaded("est", est),
                EvaluationOptions.preset(Convention.LESSON).withAlignment(AlignmentModel.NONE)
                        .withAssociation(AssociationMethod.INTERPOLATE));
        assertEquals(0, r.association().dropped());
        assertEquals(0.0, r.ate().transM().max(), POSITION_TOL_M);
        assertEquals(0.0, r.ate().rotRad().max(), ANGLE_TOL_RAD);
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void interpolationIsExactOnLinearSpatialMotion(long seed) {
        Random rnd = new Random(seed);
        double[] p0 = {10 * rnd.nextGaussian(), 10 * rnd.nextGaussian(), 10 * rnd.nextGaussian()};
        double[] v = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
        double[] q = RandomTrajectories.randomQuaternion(rnd);
        double[] tr = stamps(rnd, 300, 5.0, 0.2);
        double[] te = inside(rnd, 200, tr[0], tr[tr.length - 1]);
        EvaluationReport r = Evaluator.evaluate(loaded("gt", linearSpatial(tr, p0, v, q)),
                loaded("est", linearSpatial(te, p0, v, q)),
                EvaluationOptions.preset(Convention.LESSON, false).withAlignment(AlignmentModel.NONE)
                        .withAssociation(AssociationMethod.INTERPOLATE));
        assertEquals(0, r.association().dropped());
        assertEquals(0.0, r.ate().transM().max(), POSITION_TOL_M);
        assertEquals(0.0, r.ate().rotRad().max(), 1e-7); // angle of a rotation within rounding of identity: acos-limited
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void cropAndStrictAgreeWhenTheEstimateLiesInsideTheReference(long seed) {
        Random rnd = new Random(seed);
        PlanarTrajectory truth = RandomTrajectories.planarPath(rnd, 400, 0.1);
        PlanarTrajectory noisy = RandomTrajectories.noisy(rnd, truth, 0.05);
        int n = truth.size() - 20;
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = truth.t(i + 10) + 0.037;  // strictly inside the reference's span
            x[i] = noisy.x(i + 10);
            y[i] = noisy.y(i + 10);
            yaw[i] = noisy.yaw(i + 10);
        }
        PlanarTrajectory est = PlanarTrajectory.of(t, x, y, yaw);
        EvaluationOptions o = EvaluationOptions.preset(Convention.LESSON);
        EvaluationReport crop = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                o.withOverlap(OverlapPolicy.CROP));
        EvaluationReport strict = Evaluator.evaluate(loaded("gt", truth), loaded("est", est),
                o.withOverlap(OverlapPolicy.STRICT));
        assertEquals(crop.association().matched(), strict.association().matched());
        assertEquals(crop.ate(), strict.ate());
        assertEquals(crop.rpe(), strict.rpe());
    }

    /** n sorted distinct uniform stamps strictly inside (a, b). */
    private static double[] inside(Random rnd, int n, double a, double b) {
        double[] t = rnd.doubles(n, a + 1e-3, b - 1e-3).sorted().distinct().toArray();
        return t;
    }

    private static PlanarTrajectory linearPlanar(double[] t, double x0, double vx, double y0, double vy, double yaw) {
        int n = t.length;
        double[] x = new double[n];
        double[] y = new double[n];
        double[] h = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = x0 + vx * t[i];
            y[i] = y0 + vy * t[i];
            h[i] = yaw;
        }
        return PlanarTrajectory.of(t, x, y, h);
    }

    private static SpatialTrajectory linearSpatial(double[] t, double[] p0, double[] v, double[] q) {
        int n = t.length;
        double[][] c = new double[7][n];
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < 3; k++) {
                c[k][i] = p0[k] + v[k] * t[i];
            }
            for (int k = 0; k < 4; k++) {
                c[3 + k][i] = q[k];
            }
        }
        return SpatialTrajectory.of(t, c[0], c[1], c[2], c[3], c[4], c[5], c[6]);
    }
}
