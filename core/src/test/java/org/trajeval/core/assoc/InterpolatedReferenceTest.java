package org.trajeval.core.assoc;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.trajeval.core.geom.Rotations;
import org.trajeval.core.traj.PoseSequence;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * The SE(3) interpolated reference keeps only the bracket (segment, fraction) and computes
 * positions and rotations on demand, through a per-thread cache of matrices: every value must be
 * bit for bit the one evo's rule gives when computed directly (segment by a linear scan, f = (t -
 * t_a) / (t_b - t_a) clamped to [0, 1], 0 for a zero-length segment, positions a + f (b - a),
 * rotation the matrix of the slerp), whatever order the poses are asked in and however the
 * cache's slots collide.
 */
class InterpolatedReferenceTest {

    @Test
    void onDemandPosesEqualTheDirectlyInterpolatedPosesBitForBit() {
        Random rnd = new Random(515);
        SpatialTrajectory ref = randomReference(rnd, 3000);
        double[] stamps = queryStamps(rnd, ref, 5000);
        InterpolatedReference interp = InterpolatedReference.spatial(ref, stamps.length);
        // filled in uneven chunks, as the evaluator's threads do
        for (int from = 0; from < stamps.length; from += 777) {
            interp.fill(k -> stamps[k], from, Math.min(stamps.length, from + 777));
        }
        InterpolatedReference.Cursor cursor = new InterpolatedReference.Cursor();
        double[] r = new double[9];
        double[] uncached = new double[9];
        double[] expected = new double[12];
        // sequential, then backwards, then pose k and k + SLOTS alternately (the same cache slot)
        for (int pass = 0; pass < 3; pass++) {
            for (int i = 0; i < stamps.length; i++) {
                int k = pass == 0 ? i : pass == 1 ? stamps.length - 1 - i
                        : (i % 2 == 0 ? i / 2 : Math.min(stamps.length - 1, i / 2 + InterpolatedReference.Cursor.SLOTS));
                direct(ref, stamps[k], expected);
                interp.rotation(k, r, 0, cursor);
                interp.rotation(k, uncached, 0);
                for (int c = 0; c < 9; c++) {
                    assertBits(expected[3 + c], r[c], "rotation " + c + " of pose " + k + ", pass " + pass);
                    assertBits(expected[3 + c], uncached[c], "rotation " + c + " of pose " + k + " without a cursor");
                }
                assertBits(expected[0], interp.x(k), "x of pose " + k);
                assertBits(expected[1], interp.y(k), "y of pose " + k);
                assertBits(expected[2], interp.z(k), "z of pose " + k);
            }
        }
    }

    @Test
    void aCursorMovedToAnotherReferenceForgetsTheFirstOnesRotations() {
        Random rnd = new Random(516);
        SpatialTrajectory a = randomReference(rnd, 400);
        SpatialTrajectory b = randomReference(rnd, 400);
        double[] stamps = queryStamps(rnd, a, 300);
        InterpolatedReference ia = InterpolatedReference.spatial(a, stamps.length);
        InterpolatedReference ib = InterpolatedReference.spatial(b, stamps.length);
        ia.fill(k -> stamps[k], 0, stamps.length);
        ib.fill(k -> stamps[k], 0, stamps.length);
        InterpolatedReference.Cursor cursor = new InterpolatedReference.Cursor();
        double[] r = new double[9];
        double[] expected = new double[12];
        for (int k = 0; k < stamps.length; k++) {
            ia.rotation(k, r, 0, cursor);
            ib.rotation(k, r, 0, cursor);
            direct(b, stamps[k], expected);
            for (int c = 0; c < 9; c++) {
                assertBits(expected[3 + c], r[c], "rotation " + c + " of pose " + k + " of the second reference");
            }
        }
    }

    @Test
    void materialisedPosesEqualTheOnDemandOnes() {
        Random rnd = new Random(517);
        SpatialTrajectory ref = randomReference(rnd, 500);
        double[] stamps = queryStamps(rnd, ref, 700);
        PoseSequence poses = InterpolatedReference.spatialAt(ref, stamps);
        double[] r = new double[9];
        double[] expected = new double[12];
        for (int k = 0; k < stamps.length; k++) {
            direct(ref, stamps[k], expected);
            poses.rotation(k, r, 0);
            assertBits(expected[0], poses.x(k), "x of pose " + k);
            assertBits(expected[2], poses.z(k), "z of pose " + k);
            for (int c = 0; c < 9; c++) {
                assertBits(expected[3 + c], r[c], "rotation " + c + " of pose " + k);
            }
        }
    }

    /** evo's rule computed directly: x, y, z into out[0..3), the rotation matrix into out[3..12). */
    private static void direct(SpatialTrajectory ref, double t, double[] out) {
        int nr = ref.size();
        int idx = 0;
        while (idx < nr && ref.t(idx) < t) {
            idx++;
        }
        int s = Math.max(1, Math.min(nr - 1, idx));
        double dt = ref.t(s) - ref.t(s - 1);
        double f = dt > 0.0 ? (t - ref.t(s - 1)) / dt : 0.0;
        f = Math.max(0.0, Math.min(1.0, f));
        out[0] = ref.x(s - 1) + f * (ref.x(s) - ref.x(s - 1));
        out[1] = ref.y(s - 1) + f * (ref.y(s) - ref.y(s - 1));
        out[2] = ref.z(s - 1) + f * (ref.z(s) - ref.z(s - 1));
        double[] q0 = new double[4];
        double[] q1 = new double[4];
        double[] q = new double[4];
        ref.quaternion(s - 1, q0);
        ref.quaternion(s, q1);
        Rotations.slerp(q0, q1, f, q);
        Rotations.fromQuaternion(q[0], q[1], q[2], q[3], out, 3);
    }

    @Test
    void twoPosesSideBySideEqualTheDirectlyInterpolatedPosesBitForBit() {
        // rotationsOnce(k) as the RPE window asks (k, k + 1), with fewer, as many and more queries than
        // segments, odd ends, and references whose neighbours are equal, antipodal or a half turn apart
        Random rnd = new Random(516);
        double[] expected = new double[12];
        double[] two = new double[20];
        for (int variant = 0; variant < 2; variant++) {
            SpatialTrajectory ref = variant == 0 ? randomReference(rnd, 3001) : awkwardReference(rnd, 2999);
            for (int n : new int[] {1501, 3003, 9007}) {
                double[] stamps = queryStamps(rnd, ref, n);
                InterpolatedReference interp = InterpolatedReference.spatial(ref, n);
                interp.fill(k -> stamps[k], 0, n);
                InterpolatedReference.Cursor cursor = new InterpolatedReference.Cursor();
                for (int step : new int[] {2, 3, 1}) {
                    for (int k = 0; k + 1 < n; k += step) {
                        interp.rotationsOnce(k, two, 1, 11, cursor);
                        for (int d = 0; d < 2; d++) {
                            direct(ref, stamps[k + d], expected);
                            for (int c = 0; c < 9; c++) {
                                assertBits(expected[3 + c], two[1 + 10 * d + c], "rotation " + c + " of pose "
                                        + (k + d) + " of " + n + ", variant " + variant + ", step " + step);
                            }
                        }
                        if (k % 5 == 0) {
                            interp.rotationOnce(k + 1, two, 1, cursor); // one at a time in between
                            direct(ref, stamps[k + 1], expected);
                            assertBits(expected[3], two[1], "rotation 0 of pose " + (k + 1) + " alone");
                        }
                    }
                }
            }
        }
    }

    /** As {@link #randomReference}, each rotation equal, opposite (-q), a half turn from or near its predecessor. */
    private static SpatialTrajectory awkwardReference(Random rnd, int n) {
        SpatialTrajectory r = randomReference(rnd, n);
        double[][] c = new double[8][n];
        double[] q = new double[4];
        for (int i = 0; i < n; i++) {
            c[0][i] = r.t(i);
            c[1][i] = r.x(i);
            c[2][i] = r.y(i);
            c[3][i] = r.z(i);
            r.quaternion(i, q);
            if (i > 0) {
                double w = c[4][i - 1];
                double x = c[5][i - 1];
                double y = c[6][i - 1];
                double z = c[7][i - 1];
                switch (i % 5) {
                    case 0 -> q = new double[] {w, x, y, z};
                    case 1 -> q = new double[] {-w, -x, -y, -z};
                    case 2 -> q = new double[] {-x, w, -z, y};
                    case 3 -> q = new double[] {w + 1e-9, x, y - 1e-9, z};
                    default -> q = q.clone();
                }
            }
            c[4][i] = q[0];
            c[5][i] = q[1];
            c[6][i] = q[2];
            c[7][i] = q[3];
        }
        return SpatialTrajectory.of(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
    }

    /** A random walk with random rotations, some repeated stamps (zero-length segments). */
    private static SpatialTrajectory randomReference(Random rnd, int n) {
        double[][] c = new double[8][n];
        double t = 10.0;
        for (int i = 0; i < n; i++) {
            t += rnd.nextInt(20) == 0 ? 0.0 : 0.01 + 0.05 * rnd.nextDouble();
            c[0][i] = t;
            for (int a = 1; a < 4; a++) {
                c[a][i] = (i == 0 ? 0.0 : c[a][i - 1]) + rnd.nextGaussian();
            }
            for (int a = 4; a < 8; a++) {
                c[a][i] = rnd.nextGaussian();
            }
        }
        return SpatialTrajectory.of(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
    }

    /** Increasing stamps from before the reference's start to after its end, some on its own stamps. */
    private static double[] queryStamps(Random rnd, SpatialTrajectory ref, int n) {
        double t0 = ref.t(0) - 0.5;
        double span = ref.t(ref.size() - 1) + 0.5 - t0;
        double[] s = new double[n];
        for (int k = 0; k < n; k++) {
            s[k] = rnd.nextInt(10) == 0 ? ref.t(rnd.nextInt(ref.size())) : t0 + span * rnd.nextDouble();
        }
        Arrays.sort(s);
        return s;
    }

    private static void assertBits(double expected, double actual, String what) {
        assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual), what);
    }
}
