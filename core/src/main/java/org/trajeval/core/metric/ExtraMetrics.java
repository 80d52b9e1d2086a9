package org.trajeval.core.metric;

import org.trajeval.core.stats.ErrorStatistics;
import org.trajeval.core.traj.PoseSequence;

/**
 * Errors users ask for beside ATE and RPE (evo issues #537, #577, #649, #43), on associated and
 * aligned poses:
 * <ul>
 * <li>per-axis translation error e_x, e_y, e_z = p_est - p_ref in the reference's world frame (m),
 *     signed, so the mean is a bias;</li>
 * <li>planar heading error |wrap(yaw_est - yaw_ref)| with yaw = atan2(R_10, R_00) (rad);</li>
 * <li>speed error |v_est| - |v_ref| (m/s) over the horizon H: for every i, j is the first pose with
 *     t_j >= t_i + H and v = (p_j - p_i) / (t_j - t_i). Example: the estimate covers 1.1 m while
 *     the reference covers 1.0 m in 1 s: +0.1 m/s.</li>
 * </ul>
 *
 * @param transX statistics of e_x (m)
 * @param transY statistics of e_y (m)
 * @param transZ statistics of e_z (m)
 * @param heading statistics of the heading error (rad)
 * @param speed statistics of the speed error (m/s)
 * @param horizonS the speed horizon H (s)
 */
public record ExtraMetrics(ErrorStatistics transX, ErrorStatistics transY, ErrorStatistics transZ,
        ErrorStatistics heading, ErrorStatistics speed, double horizonS) {

    /**
     * @param ref associated reference poses
     * @param est associated, aligned estimate poses
     * @param t stamps of the pairs (s), non-decreasing
     * @param horizonS speed horizon H (s), > 0
     */
    public static ExtraMetrics compute(PoseSequence ref, PoseSequence est, double[] t, double horizonS) {
        int n = ref.size();
        double[] ex = new double[n];
        double[] ey = new double[n];
        double[] ez = new double[n];
        double[] hd = new double[n];
        double[] rr = new double[9];
        double[] re = new double[9];
        for (int i = 0; i < n; i++) {
            ex[i] = est.x(i) - ref.x(i);
            ey[i] = est.y(i) - ref.y(i);
            ez[i] = est.z(i) - ref.z(i);
            ref.rotation(i, rr, 0);
            est.rotation(i, re, 0);
            double d = Math.atan2(re[3], re[0]) - Math.atan2(rr[3], rr[0]);
            hd[i] = Math.abs(Math.atan2(Math.sin(d), Math.cos(d)));
        }
        double[] sp = new double[n];
        int m = 0;
        int j = 0;
        for (int i = 0; i < n; i++) {
            j = Math.max(j, i + 1);
            while (j < n && t[j] < t[i] + horizonS) {
                j++;
            }
            if (j >= n) {
                break;
            }
            double dt = t[j] - t[i];
            if (!(dt > 0)) {
                continue;
            }
            double ve = Math.sqrt(sq(est.x(j) - est.x(i)) + sq(est.y(j) - est.y(i)) + sq(est.z(j) - est.z(i))) / dt;
            double vr = Math.sqrt(sq(ref.x(j) - ref.x(i)) + sq(ref.y(j) - ref.y(i)) + sq(ref.z(j) - ref.z(i))) / dt;
            sp[m++] = ve - vr;
        }
        return new ExtraMetrics(ErrorStatistics.of(ex, n), ErrorStatistics.of(ey, n), ErrorStatistics.of(ez, n),
                ErrorStatistics.of(hd, n), ErrorStatistics.of(sp, m), horizonS);
    }

    private static double sq(double v) {
        return v * v;
    }
}
