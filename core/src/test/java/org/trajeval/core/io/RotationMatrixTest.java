package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

class RotationMatrixTest {
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
    void seededRandomRotationsAreRotations() {
        SplittableRandom rnd = new SplittableRandom(7);
        for (int i = 0; i < 10_000; i++) {
            double w = rnd.nextDouble(-1, 1);
            double x = rnd.nextDouble(-1, 1);
            double y = rnd.nextDouble(-1, 1);
            double z = rnd.nextDouble(-1, 1);
            double n = Math.sqrt(w * w + x * x + y * y + z * z);
            double[] r = rowMajor(matrixOf(w / n, x / n, y / n, z / n));
            assertTrue(RotationMatrix.orthonormalityError(r) < 1e-14);
            assertEquals(1.0, RotationMatrix.determinant(r), 1e-14);
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
