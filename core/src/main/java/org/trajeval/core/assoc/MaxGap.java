package org.trajeval.core.assoc;

import org.trajeval.core.traj.Trajectory;

/**
 * The longest reference gap interpolation may bridge: a fixed time, or a multiple of the
 * reference's median sampling period. An estimate pose whose bracketing reference poses lie
 * further apart is dropped, counted and located instead of being scored against a straight
 * line drawn across the hole (fr2_desk's ground truth has a 12 s hole).
 *
 * <p>Example: a 100 Hz reference (median period 0.01 s) with the default of 10 periods: gaps up
 * to 0.1 s are interpolated; an estimate pose inside a 0.5 s hole is dropped.
 *
 * @param seconds fixed limit (s), > 0; or 0 when {@code periods} is used
 * @param periods limit in median reference periods, > 0; or 0 when {@code seconds} is used
 */
public record MaxGap(double seconds, double periods) {
    /** Default: 10 median periods of the reference. */
    public static final MaxGap DEFAULT = new MaxGap(0.0, 10.0);
    /** Most intervals sampled for the median period (evenly spaced over the trajectory). */
    static final int MEDIAN_SAMPLES = 65_536;

    /** @throws IllegalArgumentException unless exactly one of the two is a positive finite number */
    public MaxGap {
        boolean s = seconds > 0.0 && Double.isFinite(seconds);
        boolean p = periods > 0.0 && Double.isFinite(periods);
        if (s == p || (!s && seconds != 0.0) || (!p && periods != 0.0)) {
            throw new IllegalArgumentException("max gap needs either seconds > 0 or periods > 0, got " + seconds
                    + " s, " + periods + " periods");
        }
    }

    /** @return a fixed limit (s) */
    public static MaxGap ofSeconds(double s) {
        return new MaxGap(s, 0.0);
    }

    /** @return the limit for this reference (s): the fixed one, or periods x its median period */
    public double limitS(Trajectory ref) {
        return seconds > 0.0 ? seconds : periods * medianPeriodS(ref);
    }

    /**
     * @return the median of t(k+1) - t(k) over up to {@value #MEDIAN_SAMPLES} evenly spaced k (s);
     *     positive intervals only (kept duplicate stamps are skipped); +inf with fewer than 2 poses
     */
    public static double medianPeriodS(Trajectory ref) {
        int n = ref.size() - 1;
        if (n < 1) {
            return Double.POSITIVE_INFINITY;
        }
        int m = Math.min(n, MEDIAN_SAMPLES);
        double[] d = new double[m];
        int c = 0;
        for (int i = 0; i < m; i++) {
            int k = (int) ((long) i * n / m);
            double h = ref.t(k + 1) - ref.t(k);
            if (h > 0.0) {
                d[c++] = h;
            }
        }
        if (c == 0) {
            return Double.POSITIVE_INFINITY;
        }
        java.util.Arrays.sort(d, 0, c);
        return c % 2 == 1 ? d[c / 2] : 0.5 * (d[c / 2 - 1] + d[c / 2]);
    }

    @Override
    public String toString() {
        return seconds > 0.0 ? seconds + " s" : periods + " median reference periods";
    }
}
