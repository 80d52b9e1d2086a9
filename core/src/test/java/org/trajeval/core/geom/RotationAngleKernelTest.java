package org.trajeval.core.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * The straight-line angle kernel ({@link Rotations#angle(double, double, double, double, double,
 * double, double, double, double)}, which {@link Rotations#angle(double[], int)} now calls), its
 * two-at-a-time form {@link Rotations#angles} and
 * {@link Rotations#toQuaternion} must give the bits of the array code they replaced
 * ({@link RotationsAsTheyWere}, verbatim from main at 4e1def5, with the JDK's atan2): seeded random
 * rotations and products of rotations, every branch of Shepperd's method (trace, m00, m11, m22),
 * exact and near half turns, the small-angle series and its edge, matrices that fail the
 * orthogonality test (polar factor first), reflections and NaN.
 */
class RotationAngleKernelTest {

    @Test
    void randomRotationsAndTheirProductsGiveTheArrayCodesAngleBitForBit() {
        Random rnd = new Random(1507);
        double[] a = new double[9];
        double[] b = new double[9];
        for (int trial = 0; trial < 100_000; trial++) {
            double scale = trial % 3 == 0 ? 1.0 : 0.5 + rnd.nextDouble(); // quaternions as read, not unit
            Rotations.fromQuaternion(scale * rnd.nextGaussian(), scale * rnd.nextGaussian(),
                    scale * rnd.nextGaussian(), scale * rnd.nextGaussian(), a, 0);
            same(a);
            // a nearby rotation, and A^T B as the error kernels form it (rounded, not exactly orthogonal)
            double h = switch (trial % 5) {
                case 0 -> rnd.nextGaussian();
                case 1 -> rnd.nextGaussian() * 1e-3; // the series branch and its edge
                case 2 -> rnd.nextGaussian() * 1e-9;
                case 3 -> Math.PI / 2 - Math.abs(rnd.nextGaussian()) * 1e-7; // near a half turn (q = angle / 2)
                default -> Math.PI / 2 * rnd.nextDouble();
            };
            double[] axis = unit(rnd);
            double[] q = {Math.cos(h), Math.sin(h) * axis[0], Math.sin(h) * axis[1], Math.sin(h) * axis[2]};
            double[] d = new double[9];
            Rotations.fromQuaternion(q[0], q[1], q[2], q[3], d, 0);
            for (int r = 0; r < 3; r++) {
                for (int c = 0; c < 3; c++) {
                    b[3 * r + c] = a[3 * r] * d[c] + a[3 * r + 1] * d[3 + c] + a[3 * r + 2] * d[6 + c];
                }
            }
            same(d);
            same(transposeTimes(a, b));
        }
    }

    @Test
    void halfTurnsIdentityAndTinyAnglesTakeEveryShepperdBranchWithTheOldBits() {
        Random rnd = new Random(1508);
        double[][] exact = {
            {1, 0, 0, 0, 1, 0, 0, 0, 1}, {1, -0.0, 0.0, -0.0, 1, -0.0, 0.0, 0.0, 1}, // identity, signed zeros
            {1, 0, 0, 0, -1, 0, 0, 0, -1}, // half turn about x: Shepperd's m00 branch
            {-1, 0, 0, 0, 1, 0, 0, 0, -1}, // about y: m11 branch
            {-1, 0, 0, 0, -1, 0, 0, 0, 1}, // about z: m22 branch
            {-1, -0.0, 0.0, 0.0, -1, -0.0, -0.0, 0.0, 1}, {0, -1, 0, 1, 0, 0, 0, 0, 1}, {0, 0, 1, 0, 1, 0, -1, 0, 0},
        };
        for (double[] m : exact) {
            same(m);
        }
        double[] m = new double[9];
        for (int trial = 0; trial < 50_000; trial++) {
            double[] axis = unit(rnd);
            double h = switch (trial % 6) {
                case 0 -> Math.PI / 2; // a half turn about a random axis (rounded)
                case 1 -> Math.PI / 2 - Math.abs(rnd.nextGaussian()) * 1e-9;
                case 2 -> Math.abs(rnd.nextGaussian()) * 1e-12; // next to the identity
                case 3 -> 0.5e-3 + rnd.nextGaussian() * 1e-9; // an angle next to the series edge 1e-3
                case 4 -> Math.PI / 2 * rnd.nextDouble();
                default -> 0.0;
            };
            Rotations.fromQuaternion(Math.cos(h), Math.sin(h) * axis[0], Math.sin(h) * axis[1],
                    Math.sin(h) * axis[2], m, 0);
            same(m);
            // the axis along one coordinate: the diagonal branches with exact zeros off the axis
            int k = trial % 3;
            double[] q = {Math.cos(h), 0, 0, 0};
            q[1 + k] = (trial % 2 == 0 ? 1 : -1) * Math.sin(h);
            Rotations.fromQuaternion(q[0], q[1], q[2], q[3], m, 0);
            same(m);
        }
    }

    @Test
    void matricesOffTheRotationGroupGoThroughThePolarFactorWithTheOldBits() {
        Random rnd = new Random(1509);
        double[] m = new double[9];
        int polar = 0;
        for (int trial = 0; trial < 30_000; trial++) {
            Rotations.fromQuaternion(rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(),
                    m, 0);
            double e = switch (trial % 5) {
                case 0 -> 1e-6; // KITTI-like: orthonormal to about 1e-6
                case 1 -> 1e-12; // at the tolerance
                case 2 -> 1e-13;
                case 3 -> 1e-2;
                default -> 0.3;
            };
            for (int k = 0; k < 9; k++) {
                m[k] += e * rnd.nextGaussian();
            }
            polar += orthogonal(m) ? 0 : 1;
            same(m);
            if (trial % 10 == 0) {
                for (int k = 0; k < 3; k++) {
                    m[k] = -m[k]; // a reflection
                }
                same(m);
            }
        }
        assertTrue(polar > 10_000, "matrices that fail the orthogonality test: " + polar);
        same(new double[] {Double.NaN, 0, 0, 0, 1, 0, 0, 0, 1});
        same(new double[] {2, 0, 0, 0, 0.5, 0, 0, 0, 1});
        same(new double[] {1e200, 0, 0, 0, 1e200, 0, 0, 0, 1e200});
    }

    /** Compares the kernel's angle (both entry points) and quaternion with the array code's, bit for bit. */
    private static void same(double[] m) {
        long want = Double.doubleToRawLongBits(RotationsAsTheyWere.angle(m, 0));
        long arr = Double.doubleToRawLongBits(Rotations.angle(m, 0));
        long loc = Double.doubleToRawLongBits(Rotations.angle(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]));
        if (want != arr || want != loc) {
            assertEquals(Double.longBitsToDouble(want) + " " + Double.longBitsToDouble(want),
                    Double.longBitsToDouble(arr) + " " + Double.longBitsToDouble(loc), "angle of " + str(m));
        }
        // two at a time: M and its transpose (another rotation, or another matrix off the group)
        double[] t = {m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]};
        long wantT = Double.doubleToRawLongBits(RotationsAsTheyWere.angle(t, 0));
        double[] two = new double[3];
        Rotations.angles(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], t[0], t[1], t[2], t[3], t[4], t[5], t[6],
                t[7], t[8], two, 1);
        if (want != Double.doubleToRawLongBits(two[1]) || wantT != Double.doubleToRawLongBits(two[2])) {
            assertEquals(Double.longBitsToDouble(want) + " " + Double.longBitsToDouble(wantT), two[1] + " " + two[2],
                    "angles of " + str(m) + " and its transpose");
        }
        double[] qa = new double[4];
        double[] qb = new double[4];
        RotationsAsTheyWere.toQuaternion(m, 0, qa);
        Rotations.toQuaternion(m, 0, qb);
        for (int k = 0; k < 4; k++) {
            if (!Double.isNaN(qa[k]) || !Double.isNaN(qb[k])) {
                assertEquals(Double.doubleToRawLongBits(qa[k]), Double.doubleToRawLongBits(qb[k]),
                        "quaternion part " + k + " of " + str(m));
            }
        }
    }

    private static boolean orthogonal(double[] m) {
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                double g = m[3 * i] * m[3 * j] + m[3 * i + 1] * m[3 * j + 1] + m[3 * i + 2] * m[3 * j + 2];
                if (!(Math.abs(g - (i == j ? 1.0 : 0.0)) <= 1e-12 + (i == j ? 1e-5 : 0.0))) {
                    return false;
                }
            }
        }
        return true;
    }

    private static double[] transposeTimes(double[] a, double[] b) {
        double[] e = new double[9];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                e[3 * r + c] = a[r] * b[c] + a[3 + r] * b[3 + c] + a[6 + r] * b[6 + c];
            }
        }
        return e;
    }

    private static double[] unit(Random rnd) {
        double x = rnd.nextGaussian();
        double y = rnd.nextGaussian();
        double z = rnd.nextGaussian();
        double n = Math.sqrt(x * x + y * y + z * z);
        return new double[] {x / n, y / n, z / n};
    }

    private static String str(double[] m) {
        return java.util.Arrays.toString(m);
    }
}
