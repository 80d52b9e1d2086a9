package org.trajeval.core.metric;

import org.trajeval.core.traj.PoseSequence;

/**
 * SE(3) products used by RPE and drift, evaluated in evo's operation order so that results
 * agree to the last digits: inv(T) = [R^T, -R^T t]; A B = [R_A R_B, R_A t_B + t_A].
 */
public final class RelativeMotion {
    private RelativeMotion() {
    }

    /** Writes inv(T_i) T_j of {@code poses} into out (R: out[0..9), t: out[9..12)). */
    static void between(PoseSequence poses, int i, int j, double[] ri, double[] rj, double[] out) {
        poses.rotation(i, ri, 0);
        poses.rotation(j, rj, 0);
        double tix = poses.x(i);
        double tiy = poses.y(i);
        double tiz = poses.z(i);
        double tjx = poses.x(j);
        double tjy = poses.y(j);
        double tjz = poses.z(j);
        inverseTimes(ri, tix, tiy, tiz, rj, tjx, tjy, tjz, out);
    }

    /**
     * out = inv(A) B for A = [ra | ta], B = [rb | tb]: rotation ra^T rb, translation
     * ra^T tb + (-ra^T ta).
     */
    public static void inverseTimes(double[] ra, double tax, double tay, double taz, double[] rb, double tbx, double tby,
            double tbz, double[] out) {
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                out[3 * r + c] = ra[r] * rb[c] + ra[3 + r] * rb[3 + c] + ra[6 + r] * rb[6 + c];
            }
        }
        for (int r = 0; r < 3; r++) {
            double inv = -(ra[r] * tax + ra[3 + r] * tay + ra[6 + r] * taz);
            out[9 + r] = ra[r] * tbx + ra[3 + r] * tby + ra[6 + r] * tbz + inv;
        }
    }

    /** @return the Frobenius norm |E - I| of the 4x4 matrix [R t; 0 1] held in e (R: e[0..9), t: e[9..12)) */
    static double distanceFromIdentity(double[] e) {
        double sum = 0.0;
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                double v = e[3 * r + c] - (r == c ? 1.0 : 0.0);
                sum += v * v;
            }
            sum += e[9 + r] * e[9 + r];
        }
        return Math.sqrt(sum);
    }
}
