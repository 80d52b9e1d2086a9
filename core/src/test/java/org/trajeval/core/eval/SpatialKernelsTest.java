package org.trajeval.core.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.trajeval.core.align.Alignment;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.AssociationOptions;
import org.trajeval.core.assoc.InterpolatedReference;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.assoc.TimeAssociation;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/**
 * The 3x3 ATE and RPE kernels of {@link AssociatedColumns}, straight-line code on locals, must give
 * the per-pose errors of the array kernels they replaced ({@link MatrixKernelsAsTheyWere}) bit for
 * bit ({@link Double#doubleToRawLongBits}): seeded random SE(3) pairs whose errors are ordinary,
 * zero (the same rotations), tiny (the small-angle series), half turns and near half turns (Shepperd's
 * diagonal branches), and KITTI-like matrix trajectories orthonormal only to 1e-6 (polar factor
 * first), and planar pairs through the 3x3 kernels; every alignment model, interpolated and nearest association, the pairs of every RPE rule,
 * and the ATE both computed on its own and taken from the RPE pass (start poses of SE(3) pairs).
 */
class SpatialKernelsTest {
    private static final String[] KINDS = {"ordinary", "same rotations", "tiny errors", "half turn",
        "near half turn", "KITTI-like matrices", "planar pairs (rotations about +z)"};

    @Test
    void straightLineKernelsGiveTheArrayKernelsErrorsBitForBit() {
        Random rnd = new Random(1510);
        int runs = 0;
        for (int kind = 0; kind < KINDS.length; kind++) {
            int n = 1800 + 61 * kind;
            Trajectory ref;
            Trajectory est;
            if (kind == 6) {
                PlanarTrajectory planarRef = PlanarErrorsTest.randomPath(rnd, n, 1.0, 3);
                ref = planarRef;
                est = PlanarErrorsTest.estimateOf(rnd, planarRef, 1.0, 3);
            } else {
                ref = reference(rnd, n, kind);
                est = estimate(rnd, (SpatialTrajectory) ref, kind);
            }
            for (AssociationMethod assoc : new AssociationMethod[] {AssociationMethod.INTERPOLATE,
                AssociationMethod.NEAREST}) {
                for (AlignmentModel model : AlignmentModel.values()) {
                    AssociatedColumns fast = associate(ref, est, assoc);
                    AlignmentTransform tf;
                    try {
                        tf = Alignment.fit(model, fast, -1, "est");
                    } catch (RuntimeException degenerate) {
                        continue;
                    }
                    fast.alignForMatrixKernels(tf);
                    assertFalse(fast.planarKernels(), "the 3x3 kernels are under test");
                    MatrixKernelsAsTheyWere old = new MatrixKernelsAsTheyWere(fast, tf);
                    String what = KINDS[kind] + " " + assoc + " " + model;
                    sameAte(fast, old, what + " (ATE computed)");
                    samePairs(fast, old, what);
                    sameAte(fast, old, what + " (ATE after the RPE)");
                    runs++;
                }
            }
        }
        assertTrue(runs >= KINDS.length * 2 * 4, "runs " + runs);
    }

    @Test
    void theRpePassLeavesTheStartPosesAteRotationForSpatialPairs() {
        // the route "ATE rotation taken from the RPE pass" must really be taken, or the test above
        // would compare only the computed route: for an interpolated reference and for matched pairs
        for (AssociationMethod assoc : new AssociationMethod[] {AssociationMethod.INTERPOLATE,
            AssociationMethod.NEAREST}) {
            Random rnd = new Random(1511);
            SpatialTrajectory ref = reference(rnd, 500, 0);
            SpatialTrajectory est = estimate(rnd, ref, 0);
            AssociatedColumns fast = associate(ref, est, assoc);
            AlignmentTransform tf = Alignment.fit(AlignmentModel.SE3, fast, -1, "est");
            fast.align(tf);
            AssociatedColumns.Scratch s = new AssociatedColumns.Scratch();
            fast.rpe(3, 9, s);
            // a window that never met pose 3: only the value the RPE left can answer without computing
            AssociatedColumns.Scratch fresh = new AssociatedColumns.Scratch();
            double[] trans = new double[fast.size()];
            double[] rot = new double[fast.size()];
            fast.ateInto(3, 4, trans, rot, fresh);
            double viaRpe = rot[3];
            AssociatedColumns computed = associate(ref, est, assoc);
            computed.align(tf);
            computed.ate(3, s);
            assertEquals(Double.doubleToRawLongBits(s.rotError), Double.doubleToRawLongBits(viaRpe), assoc.toString());
            assertEquals(new MatrixKernelsAsTheyWere(fast, tf).ate(3)[1], viaRpe, 0.0, assoc.toString());
            assertTrue(fast.ateRotationKnown(3) && !computed.ateRotationKnown(3), assoc.toString());
        }
    }

    private static AssociatedColumns associate(Trajectory ref, Trajectory est, AssociationMethod assoc) {
        if (assoc == AssociationMethod.INTERPOLATE) {
            int m = est.size();
            InterpolatedReference interp = ref instanceof SpatialTrajectory s ? InterpolatedReference.spatial(s, m)
                    : InterpolatedReference.planar((PlanarTrajectory) ref, m);
            interp.fill(est::t, 0, m);
            return AssociatedColumns.interpolated(ref, est, interp, 0, m, 0.0);
        }
        TimeAssociation.NearestPairs np = TimeAssociation.nearestPairs(ref, est,
                new AssociationOptions(AssociationMethod.NEAREST, 0.02, 0.0, OverlapPolicy.CROP), "gt", "est");
        return AssociatedColumns.matched(ref, est, np.reference(), np.estimate(), np.count(), 0.0,
                Parallelism.SEQUENTIAL);
    }

    /** Pose by pose, then in ranges as the evaluator's chunks ask for them (two at a time, odd ends). */
    private static void sameAte(AssociatedColumns fast, MatrixKernelsAsTheyWere old, String what) {
        AssociatedColumns.Scratch s = new AssociatedColumns.Scratch();
        int m = fast.size();
        for (int k = 0; k < m; k++) {
            fast.ate(k, s);
            same(old.ate(k), s, what + " pose " + k);
        }
        double[] trans = new double[m];
        double[] rot = new double[m];
        fast.ateInto(0, 1, trans, rot, new AssociatedColumns.Scratch());
        fast.ateInto(1, 700, trans, rot, new AssociatedColumns.Scratch());
        fast.ateInto(700, m, trans, rot, s);
        for (int k = 0; k < m; k++) {
            double[] want = old.ate(k);
            if (Double.doubleToRawLongBits(want[0]) != Double.doubleToRawLongBits(trans[k])
                    || Double.doubleToRawLongBits(want[1]) != Double.doubleToRawLongBits(rot[k])) {
                assertEquals(want[0] + " m " + want[1] + " rad", trans[k] + " m " + rot[k] + " rad",
                        what + " pose " + k + " in a range");
            }
        }
    }

    /** The pairs of every rule: (i, i + d) from every start and consecutively, and t_j &gt;= t_i + delta. */
    private static void samePairs(AssociatedColumns fast, MatrixKernelsAsTheyWere old, String what) {
        int m = fast.size();
        for (int d : new int[] {1, 7, 1100}) {
            AssociatedColumns.Scratch s = new AssociatedColumns.Scratch();
            for (int i = 0; i + d < m; i++) {
                if (i % 1000 == 0) {
                    s = new AssociatedColumns.Scratch(); // a new chunk: a new cache
                    s.posesInRuns = true; // every start: the window computes poses two at a time, as EveryStart's
                }
                fast.rpe(i, i + d, s);
                same(old.rpe(i, i + d), s, what + " frames " + d + " pair " + i);
            }
            s.posesInRuns = false; // consecutive pairs: one pose at a time, as Stride's for d > 1
            for (int i = 0; i + d < m; i += d) {
                fast.rpe(i, i + d, s);
                same(old.rpe(i, i + d), s, what + " consecutive frames " + d + " pair " + i);
            }
        }
        for (double delta : new double[] {0.05, 1.0}) {
            AssociatedColumns.Scratch s = new AssociatedColumns.Scratch();
            s.posesInRuns = true;
            int j = 0;
            for (int i = 0; i < m; i++) {
                j = Math.max(j, i);
                while (j < m && fast.stamp(j) < fast.stamp(i) + delta) {
                    j++;
                }
                if (j >= m) {
                    break;
                }
                fast.rpe(i, j, s);
                same(old.rpe(i, j), s, what + " seconds " + delta + " pair " + i + " " + j);
            }
        }
    }

    private static void same(double[] expected, AssociatedColumns.Scratch actual, String what) {
        if (Double.doubleToRawLongBits(expected[0]) != Double.doubleToRawLongBits(actual.transError)
                || Double.doubleToRawLongBits(expected[1]) != Double.doubleToRawLongBits(actual.rotError)) {
            assertEquals(expected[0] + " m " + expected[1] + " rad", actual.transError + " m " + actual.rotError + " rad",
                    what);
        }
    }

    /**
     * A random SE(3) reference: stamps about 0.01 s apart, positions a random walk (m), the
     * orientation a random walk of quaternions that are not unit (as read from files); for the
     * KITTI-like kind, rotation matrices with every entry off by about 1e-6.
     */
    static SpatialTrajectory reference(Random rnd, int n, int kind) {
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] z = new double[n];
        double[][] q = new double[4][n];
        double tt = 0;
        double[] p = {0, 0, 0};
        double[] h = {1, 0, 0, 0};
        for (int i = 0; i < n; i++) {
            tt += 0.01 * (0.5 + rnd.nextDouble());
            t[i] = tt;
            for (int k = 0; k < 3; k++) {
                p[k] += rnd.nextGaussian();
            }
            x[i] = p[0];
            y[i] = p[1];
            z[i] = p[2];
            for (int k = 0; k < 4; k++) {
                h[k] += 0.2 * rnd.nextGaussian();
                q[k][i] = h[k] * (1 + 0.01 * rnd.nextGaussian());
            }
        }
        SpatialTrajectory ref = SpatialTrajectory.of(t, x, y, z, q[0], q[1], q[2], q[3]);
        return kind == 5 ? asMatrices(ref, rnd) : ref;
    }

    /**
     * An estimate of the reference: stamps just after the reference's (inside its span), positions
     * moved rigidly with noise, rotations g R_ref d with a fixed g and a per-pose d of the kind's
     * size: random, none, about 1e-9 rad, a half turn or a half turn less 1e-7 rad about a random axis.
     */
    static SpatialTrajectory estimate(Random rnd, SpatialTrajectory ref, int kind) {
        int n = ref.size() - 2;
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] z = new double[n];
        double[][] q = new double[4][n];
        double[] g = {Math.cos(0.2), 0.6 * Math.sin(0.2), 0, 0.8 * Math.sin(0.2)};
        double[] r = new double[4];
        for (int i = 0; i < n; i++) {
            int k = i + 1;
            t[i] = ref.t(k) + (kind == 1 ? 0.0 : 0.003 * (ref.t(k + 1) - ref.t(k)));
            x[i] = 0.8 * ref.x(k) - 0.6 * ref.y(k) + 3 + 0.1 * rnd.nextGaussian();
            y[i] = 0.6 * ref.x(k) + 0.8 * ref.y(k) - 1 + 0.1 * rnd.nextGaussian();
            z[i] = ref.z(k) + 0.5 + 0.1 * rnd.nextGaussian();
            ref.quaternion(k, r);
            double half = switch (kind) {
                case 0, 5 -> 0.05 * rnd.nextGaussian();
                case 1 -> 0.0;
                case 2 -> 1e-9 * rnd.nextGaussian();
                case 3 -> Math.PI / 2;
                default -> Math.PI / 2 - 0.5e-7;
            };
            double[] a = unit(rnd);
            double[] d = {Math.cos(half), Math.sin(half) * a[0], Math.sin(half) * a[1], Math.sin(half) * a[2]};
            double[] rd = times(r, d);
            double[] e = kind == 1 ? r : times(g, rd);
            if (kind == 1) {
                x[i] = ref.x(k) + 0.1 * rnd.nextGaussian();
                y[i] = ref.y(k);
                z[i] = ref.z(k);
            }
            for (int c = 0; c < 4; c++) {
                q[c][i] = e[c];
            }
        }
        SpatialTrajectory est = SpatialTrajectory.of(t, x, y, z, q[0], q[1], q[2], q[3]);
        return kind == 5 ? asMatrices(est, rnd) : est;
    }

    /** The trajectory with its rotations as matrices, each entry moved by about 1e-6 (KITTI's precision). */
    private static SpatialTrajectory asMatrices(SpatialTrajectory s, Random rnd) {
        int n = s.size();
        double[] r = new double[9 * n];
        for (int i = 0; i < n; i++) {
            s.rotation(i, r, 9 * i);
            for (int k = 0; k < 9; k++) {
                r[9 * i + k] += 1e-6 * rnd.nextGaussian();
            }
        }
        double[] x = new double[n];
        double[] y = new double[n];
        double[] z = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = s.x(i);
            y[i] = s.y(i);
            z[i] = s.z(i);
        }
        return SpatialTrajectory.ofMatrices(s.timestamps(), x, y, z, r);
    }

    /** Hamilton product a b of quaternions (w, x, y, z). */
    private static double[] times(double[] a, double[] b) {
        return new double[] {a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3],
            a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2],
            a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1],
            a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0]};
    }

    private static double[] unit(Random rnd) {
        double x = rnd.nextGaussian();
        double y = rnd.nextGaussian();
        double z = rnd.nextGaussian();
        double n = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / n, y / n, z / n};
    }
}
