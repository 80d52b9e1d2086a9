package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class RotationMatrixTest {
    /** Round trip quaternion -> matrix -> quaternion in double precision. */
    private static final double ROUND_TRIP_TOL = 1e-14;

    /** @return R(q) for a unit quaternion (Hamilton, active), rows then columns */
    static double[][] matrixOf(double w, double x, double y, double z) {
        return new double[][] {
            {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
            {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
            {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
    }

    private static double[] rowMajor(double[][] m) {
        return new double[] {m[0][0], m[0][1], m[0][2], m[1][0], m[1][1], m[1][2], m[2][0], m[2][1], m[2][2]};
    }

    @Test
    void quarterTurnAboutZIsCos45Sin45() {
        // the Javadoc's worked example: R = [[0,-1,0],[1,0,0],[0,0,1]] maps x to y
        double[] q = new double[4];
        RotationMatrix.toQuaternion(new double[] {0, -1, 0, 1, 0, 0, 0, 0, 1}, q);
        assertEquals(Math.sqrt(0.5), q[0], ROUND_TRIP_TOL);
        assertEquals(0.0, q[1], ROUND_TRIP_TOL);
        assertEquals(0.0, q[2], ROUND_TRIP_TOL);
        assertEquals(Math.sqrt(0.5), q[3], ROUND_TRIP_TOL);
    }

    @Test
    void halfTurnsUseTheLargestDiagonalAndRecoverTheAxis() {
        // 180 deg about x, y, z: trace = -1, so each goes through a different Shepperd branch
        double[][] diagonals = {{1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
        for (int axis = 0; axis < 3; axis++) {
            double[] d = diagonals[axis];
            double[] q = new double[4];
            RotationMatrix.toQuaternion(new double[] {d[0], 0, 0, 0, d[1], 0, 0, 0, d[2]}, q);
            assertEquals(0.0, q[0], ROUND_TRIP_TOL);
            assertEquals(1.0, Math.abs(q[1 + axis]), ROUND_TRIP_TOL);
        }
    }

    @Test
    void seededRandomRotationsRoundTripThroughTheMatrix() {
        SplittableRandom rnd = new SplittableRandom(7);
        double[] q = new double[4];
        for (int i = 0; i < 10_000; i++) {
            double w = rnd.nextDouble(-1, 1);
            double x = rnd.nextDouble(-1, 1);
            double y = rnd.nextDouble(-1, 1);
            double z = rnd.nextDouble(-1, 1);
            double n = Math.sqrt(w * w + x * x + y * y + z * z);
            double s = w < 0 ? -1 : 1;
            w *= s / n;
            x *= s / n;
            y *= s / n;
            z *= s / n;
            double[] r = rowMajor(matrixOf(w, x, y, z));
            assertTrue(RotationMatrix.orthonormalityError(r) < 1e-14);
            assertEquals(1.0, RotationMatrix.determinant(r), 1e-14);
            RotationMatrix.toQuaternion(r, q);
            assertEquals(w, q[0], ROUND_TRIP_TOL);
            assertEquals(x, q[1], ROUND_TRIP_TOL);
            assertEquals(y, q[2], ROUND_TRIP_TOL);
            assertEquals(z, q[3], ROUND_TRIP_TOL);
        }
    }

    @Test
    void scaledMatrixAndReflectionAreNotRotations() {
        double[] scaled = {2, 0, 0, 0, 2, 0, 0, 0, 2};
        assertEquals(3.0, RotationMatrix.orthonormalityError(scaled), 0.0); // 2*2 - 1
        double[] reflection = {1, 0, 0, 0, 1, 0, 0, 0, -1};
        assertEquals(0.0, RotationMatrix.orthonormalityError(reflection), 0.0);
        assertEquals(-1.0, RotationMatrix.determinant(reflection), 0.0);
    }
}
