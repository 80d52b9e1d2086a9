package org.trajeval.core.io;

/** A 3x3 matrix read from a file, row-major {@code r[3*row + col]}: how far it is from a rotation. */
final class RotationMatrix {
    private RotationMatrix() {
    }

    /** @return max over entries of |R^T R - I| (0 for an exact rotation) */
    static double orthonormalityError(double[] r) {
        double worst = 0.0;
        for (int i = 0; i < 3; i++) {
            for (int j = i; j < 3; j++) {
                double dot = r[i] * r[j] + r[3 + i] * r[3 + j] + r[6 + i] * r[6 + j];
                worst = Math.max(worst, Math.abs(dot - (i == j ? 1.0 : 0.0)));
            }
        }
        return worst;
    }

    /** @return det R (+1 for a rotation, -1 for a reflection) */
    static double determinant(double[] r) {
        return r[0] * (r[4] * r[8] - r[5] * r[7]) - r[1] * (r[3] * r[8] - r[5] * r[6])
                + r[2] * (r[3] * r[7] - r[4] * r[6]);
    }
}
