package org.trajeval.core.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * {@link PlanarAngle} must return {@link Rotations#angle} of the 3x3 matrix
 * [[m00, m01, 0], [m10, m11, 0], [0, 0, 1]] bit for bit, whatever the signs of its zeros (the
 * matrix kernels produce +0 or -0 there): seeded random blocks of every kind its branches meet.
 */
class PlanarAngleTest {

    @Test
    void rotationBlocksGiveTheMatrixAngleBitForBitAtEveryAngle() {
        Random rnd = new Random(15);
        for (int trial = 0; trial < 200_000; trial++) {
            double yaw = switch (trial % 6) {
                case 0 -> (rnd.nextDouble() - 0.5) * 2 * Math.PI; // anywhere
                case 1 -> rnd.nextGaussian() * 1e-3; // the small-angle series branch and its edge
                case 2 -> rnd.nextGaussian() * 1e-9; // near 0
                case 3 -> Math.PI - Math.abs(rnd.nextGaussian()) * 1e-7; // near +pi (Shepperd's m22 branch)
                case 4 -> -Math.PI + Math.abs(rnd.nextGaussian()) * 1e-7; // near -pi
                default -> (rnd.nextDouble() - 0.5) * 200 * Math.PI; // many turns
            };
            double c = Math.cos(yaw);
            double s = Math.sin(yaw);
            // a product of two rotations, as the kernels form them: cos/sin rounded twice
            double yaw2 = rnd.nextGaussian();
            double c2 = Math.cos(yaw2);
            double s2 = Math.sin(yaw2);
            double m00 = c * c2 + s * s2;
            double m01 = c * -s2 + s * c2;
            double m10 = -s * c2 + c * s2;
            double m11 = -s * -s2 + c * c2;
            sameAsMatrix(c, -s, s, c, rnd);
            sameAsMatrix(m00, m01, m10, m11, rnd);
        }
    }

    @Test
    void exactAnglesAndSignedZerosGiveTheMatrixAngle() {
        Random rnd = new Random(16);
        double[][] blocks = {
            {1, 0, 0, 1}, {1, -0.0, 0.0, 1}, {-1, 0, 0, -1}, {-1, -0.0, -0.0, -1}, {0, -1, 1, 0}, {0, 1, -1, 0},
            {-0.0, -1, 1, -0.0}, {Math.cos(Math.PI), -Math.sin(Math.PI), Math.sin(Math.PI), Math.cos(Math.PI)},
            {Math.cos(1e-3), -Math.sin(1e-3), Math.sin(1e-3), Math.cos(1e-3)},
            {Math.cos(Math.nextUp(1e-3)), -Math.sin(Math.nextUp(1e-3)), Math.sin(Math.nextUp(1e-3)),
                Math.cos(Math.nextUp(1e-3))},
        };
        for (double[] b : blocks) {
            sameAsMatrix(b[0], b[1], b[2], b[3], rnd);
        }
    }

    @Test
    void nonOrthogonalBlocksAndReflectionsGiveTheMatrixAngle() {
        Random rnd = new Random(17);
        for (int trial = 0; trial < 20_000; trial++) {
            double yaw = (rnd.nextDouble() - 0.5) * 2 * Math.PI;
            double c = Math.cos(yaw);
            double s = Math.sin(yaw);
            double e = switch (trial % 4) {
                case 0 -> 1e-6; // polar factor first (KITTI-like products)
                case 1 -> 1e-12; // at the orthogonality tolerance
                case 2 -> 1e-2;
                default -> 0.0;
            };
            double m00 = c + e * rnd.nextGaussian();
            double m01 = -s + e * rnd.nextGaussian();
            double m10 = s + e * rnd.nextGaussian();
            double m11 = c + e * rnd.nextGaussian();
            sameAsMatrix(m00, m01, m10, m11, rnd);
            sameAsMatrix(c, s, s, -c, rnd); // a reflection: Shepperd's m00 or m11 branch
            sameAsMatrix(-c, s, s, c, rnd);
        }
        sameAsMatrix(Double.NaN, 0, 0, 1, rnd);
        sameAsMatrix(2, 0, 0, 0.5, rnd);
    }

    @Test
    void twoBlocksSideBySideGiveEachBlocksMatrixAngle() {
        // reference: Rotations.angle of each 3x3 matrix; the pairs mix every kind of block, so that
        // either one (or both) may need the general path
        Random rnd = new Random(19);
        for (int trial = 0; trial < 100_000; trial++) {
            double[] a = block(rnd, trial % 7);
            double[] b = block(rnd, rnd.nextInt(7));
            double[] out = {Double.NaN, 7.0, 7.0, Double.NaN};
            PlanarAngle.two(a[0], a[1], a[2], a[3], b[0], b[1], b[2], b[3], out, 1);
            double ea = Rotations.angle(new double[] {a[0], a[1], 0, a[2], a[3], 0, 0, 0, 1}, 0);
            double eb = Rotations.angle(new double[] {b[0], b[1], 0, b[2], b[3], 0, 0, 0, 1}, 0);
            int t = trial;
            assertEquals(Double.doubleToRawLongBits(ea), Double.doubleToRawLongBits(out[1]), () -> "first of pair " + t);
            assertEquals(Double.doubleToRawLongBits(eb), Double.doubleToRawLongBits(out[2]), () -> "second of pair " + t);
            assertTrue(Double.isNaN(out[0]) && Double.isNaN(out[3]), "only out[o] and out[o + 1] are written");
        }
    }

    /** A block of kind 0 any rotation, 1 small angle, 2 near +-pi, 3 a product of two rotations, 4 off orthogonal, 5 a reflection, 6 NaN. */
    private static double[] block(Random rnd, int kind) {
        double yaw = switch (kind) {
            case 1 -> rnd.nextGaussian() * 1e-3;
            case 2 -> (rnd.nextBoolean() ? Math.PI : -Math.PI) - Math.signum(rnd.nextGaussian()) * 1e-7;
            default -> (rnd.nextDouble() - 0.5) * 2 * Math.PI;
        };
        double c = Math.cos(yaw);
        double s = Math.sin(yaw);
        double c2 = Math.cos(0.3);
        double s2 = Math.sin(0.3);
        double e = 1e-6 * rnd.nextGaussian();
        return switch (kind) {
            case 3 -> new double[] {c * c2 + s * s2, c * -s2 + s * c2, -s * c2 + c * s2, -s * -s2 + c * c2};
            case 4 -> new double[] {c + e, -s, s, c - e};
            case 5 -> new double[] {c, s, s, -c};
            case 6 -> new double[] {Double.NaN, 0, 0, 1};
            default -> new double[] {c, -s, s, c};
        };
    }

    @Test
    void rootOfSquareIsTheSquareRootOfTheSquareBitForBitAtEveryExponent() {
        // reference: Math.sqrt(x * x) itself, on seeded mantissas at every binary exponent (subnormals
        // included) and at the edges of the range where |x| is returned (2^-511, 2^511)
        Random rnd = new Random(18);
        int whereAbsWouldBeWrong = 0;
        for (int exp = -1074; exp <= 1023; exp++) {
            for (int k = 0; k < 64; k++) {
                double x = Math.scalb(1.0 + rnd.nextDouble(), exp);
                x = rnd.nextBoolean() ? x : -x;
                sameAsRootOfSquare(x);
                if (Math.sqrt(x * x) != Math.abs(x)) {
                    whereAbsWouldBeWrong++;
                }
            }
        }
        double[] edges = {0x1p-511, 0x1p511, 0x1p-537 + 0x1p-589, 0.0, -0.0, Double.MIN_VALUE, Double.MIN_NORMAL,
            Double.MAX_VALUE, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NaN, 1.0, Math.nextDown(2.0)};
        for (double e : edges) {
            for (double x : new double[] {e, -e, Math.nextUp(e), Math.nextDown(e)}) {
                sameAsRootOfSquare(x);
            }
        }
        // the sweep reaches the squares that underflow or overflow, where |x| alone would differ
        assertTrue(whereAbsWouldBeWrong > 1000, "values where |x| differs from sqrt(x * x): " + whereAbsWouldBeWrong);
    }

    private static void sameAsRootOfSquare(double x) {
        assertEquals(Double.doubleToRawLongBits(Math.sqrt(x * x)), Double.doubleToRawLongBits(PlanarAngle.rootOfSquare(x)),
                () -> "x = " + x + " (" + Double.toHexString(x) + ")");
    }

    /** Compares with the matrix angle for a random choice of signs of the four zeros. */
    private static void sameAsMatrix(double m00, double m01, double m10, double m11, Random rnd) {
        double[] r = {m00, m01, zero(rnd), m10, m11, zero(rnd), zero(rnd), zero(rnd), 1.0};
        double expected = Rotations.angle(r, 0);
        double actual = PlanarAngle.of(m00, m01, m10, m11);
        assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual),
                () -> "block " + m00 + " " + m01 + " " + m10 + " " + m11 + ": matrix " + expected + " planar "
                        + actual);
    }

    private static double zero(Random rnd) {
        return rnd.nextBoolean() ? 0.0 : -0.0;
    }
}
