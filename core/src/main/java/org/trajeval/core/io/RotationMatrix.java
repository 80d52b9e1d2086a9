package org.trajeval.core.io;

/**
 * A 3x3 rotation matrix read from a file, row-major {@code r[3*row + col]}: its distance from
 * a rotation and its unit quaternion.
 */
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

    /**
     * Unit quaternion of a rotation matrix by Shepperd's method: the largest of
     * {@code 4 qw^2 = 1 + tr R}, {@code 4 qx^2 = 1 + r11 - r22 - r33}, ... is taken under the
     * square root, so the division never loses precision. Result normalised, with qw >= 0.
     * Worked example: R = [[0,-1,0],[1,0,0],[0,0,1]] (+90 deg about z) gives
     * q = (cos 45 deg, 0, 0, sin 45 deg).
     *
     * @param r row-major 3x3 matrix, close to a rotation
     * @param q receives qw, qx, qy, qz
     */
    static void toQuaternion(double[] r, double[] q) {
        double r00 = r[0];
        double r01 = r[1];
        double r02 = r[2];
        double r10 = r[3];
        double r11 = r[4];
        double r12 = r[5];
        double r20 = r[6];
        double r21 = r[7];
        double r22 = r[8];
        double trace = r00 + r11 + r22;
        double w;
        double x;
        double y;
        double z;
        if (trace >= r00 && trace >= r11 && trace >= r22) {
            double s = 2.0 * Math.sqrt(1.0 + trace);
            w = 0.25 * s;
            x = (r21 - r12) / s;
            y = (r02 - r20) / s;
            z = (r10 - r01) / s;
        } else if (r00 >= r11 && r00 >= r22) {
            double s = 2.0 * Math.sqrt(1.0 + r00 - r11 - r22);
            w = (r21 - r12) / s;
            x = 0.25 * s;
            y = (r01 + r10) / s;
            z = (r02 + r20) / s;
        } else if (r11 >= r22) {
            double s = 2.0 * Math.sqrt(1.0 + r11 - r00 - r22);
            w = (r02 - r20) / s;
            x = (r01 + r10) / s;
            y = 0.25 * s;
            z = (r12 + r21) / s;
        } else {
            double s = 2.0 * Math.sqrt(1.0 + r22 - r00 - r11);
            w = (r10 - r01) / s;
            x = (r02 + r20) / s;
            y = (r12 + r21) / s;
            z = 0.25 * s;
        }
        double norm = Math.sqrt(w * w + x * x + y * y + z * z);
        double sign = w < 0 ? -1.0 : 1.0;
        q[0] = sign * w / norm;
        q[1] = sign * x / norm;
        q[2] = sign * y / norm;
        q[3] = sign * z / norm;
    }
}
