package org.trajeval.core.assoc;

import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/**
 * Estimates a constant offset between the estimate's clock and the reference's by
 * cross-correlating their angular speeds, which no alignment changes. The offset is the value
 * to add to the estimate's stamps ({@code --t-offset}): an estimate whose clock runs 0.3 s ahead
 * gets -0.3 s.
 *
 * <p>Both angular speeds |omega| = angle(R_k^T R_{k+1}) / (t_{k+1} - t_k) (rad/s) are resampled
 * on one grid of step h (the larger median period of the two, at least {@value #MIN_STEP_S} s);
 * the normalised cross-correlation is computed for every lag within +-maxLag, and the peak is
 * refined by a parabola through it and its two neighbours. The uncertainty is half the width
 * of the peak where the correlation stays within 1 % of its top, at least h / 10.
 */
public final class ClockOffset {
    /** Smallest grid step (s). */
    static final double MIN_STEP_S = 1e-3;
    /** Most grid samples (longer overlaps use a coarser grid). */
    static final int MAX_SAMPLES = 200_000;

    private ClockOffset() {
    }

    /**
     * @param offsetS the offset to add to the estimate's stamps (s)
     * @param uncertaintyS half-width of the correlation peak (s)
     * @param correlation normalised cross-correlation at the peak, in [-1, 1]
     * @param stepS grid step (s)
     */
    public record Estimate(double offsetS, double uncertaintyS, double correlation, double stepS) {
    }

    /**
     * @param maxLagS largest offset searched, either sign (s), > 0
     * @return the estimate, or {@code null} when the trajectories do not overlap enough at any lag
     */
    public static Estimate estimate(Trajectory reference, Trajectory estimate, double maxLagS) {
        SpatialTrajectory ref = reference.toSpatial();
        SpatialTrajectory est = estimate.toSpatial();
        double h = Math.max(MIN_STEP_S, Math.max(MaxGap.medianPeriodS(ref), MaxGap.medianPeriodS(est)));
        double lo = Math.max(ref.t(0), est.t(0) - maxLagS);
        double hi = Math.min(ref.t(ref.size() - 1), est.t(est.size() - 1) + maxLagS);
        if (!(hi - lo > 2 * h) || !Double.isFinite(h)) {
            return null;
        }
        h = Math.max(h, (hi - lo) / MAX_SAMPLES);
        int lags = (int) Math.ceil(maxLagS / h);
        double[] wr = speedOnGrid(ref, ref.t(0), h, (int) ((ref.t(ref.size() - 1) - ref.t(0)) / h) + 1);
        double r0 = ref.t(0);
        double e0 = est.t(0);
        double[] we = speedOnGrid(est, e0, h, (int) ((est.t(est.size() - 1) - e0) / h) + 1);
        double[] c = new double[2 * lags + 1];
        int best = -1;
        for (int k = -lags; k <= lags; k++) {
            // estimate grid point j (time e0 + j h) meets the reference at e0 + j h + k h
            double shift = (e0 - r0) / h + k;
            c[k + lags] = correlation(wr, we, shift);
            if (!Double.isNaN(c[k + lags]) && (best < 0 || c[k + lags] > c[best])) {
                best = k + lags;
            }
        }
        if (best < 0) {
            return null;
        }
        double sub = 0.0;
        if (best > 0 && best < c.length - 1 && !Double.isNaN(c[best - 1]) && !Double.isNaN(c[best + 1])) {
            double den = c[best - 1] - 2 * c[best] + c[best + 1];
            sub = den < 0 ? 0.5 * (c[best - 1] - c[best + 1]) / den : 0.0;
        }
        int left = best;
        while (left > 0 && c[left - 1] >= c[best] - 0.01 * Math.abs(c[best])) {
            left--;
        }
        int right = best;
        while (right < c.length - 1 && c[right + 1] >= c[best] - 0.01 * Math.abs(c[best])) {
            right++;
        }
        double offset = (best - lags + sub) * h;
        return new Estimate(offset, Math.max(h / 10, 0.5 * (right - left) * h), c[best], h);
    }

    /** Normalised correlation of a(i + shift) with b(j) over their overlap (a linearly interpolated). */
    private static double correlation(double[] a, double[] b, double shift) {
        double sa = 0;
        double sb = 0;
        double saa = 0;
        double sbb = 0;
        double sab = 0;
        int n = 0;
        for (int j = 0; j < b.length; j++) {
            double x = j + shift;
            int i = (int) Math.floor(x);
            if (i < 0 || i + 1 >= a.length) {
                continue;
            }
            double f = x - i;
            double va = a[i] + f * (a[i + 1] - a[i]);
            double vb = b[j];
            sa += va;
            sb += vb;
            saa += va * va;
            sbb += vb * vb;
            sab += va * vb;
            n++;
        }
        if (n < 10) {
            return Double.NaN;
        }
        double cov = sab - sa * sb / n;
        double va = saa - sa * sa / n;
        double vb = sbb - sb * sb / n;
        return va > 0 && vb > 0 ? cov / Math.sqrt(va * vb) : Double.NaN;
    }

    /** Angular speed (rad/s) at t0 + g h, g = 0..n-1, linear between the midpoints of the pose intervals. */
    private static double[] speedOnGrid(SpatialTrajectory t, double t0, double h, int n) {
        int m = t.size() - 1;
        double[] mid = new double[m];
        double[] w = new double[m];
        double[] ri = new double[9];
        double[] rj = new double[9];
        int c = 0;
        for (int k = 0; k < m; k++) {
            double dt = t.t(k + 1) - t.t(k);
            if (!(dt > 0)) {
                continue;
            }
            t.poses().rotation(k, ri, 0);
            t.poses().rotation(k + 1, rj, 0);
            // trace(R_k^T R_{k+1}) = sum of elementwise products
            double tr = 0;
            for (int q = 0; q < 9; q++) {
                tr += ri[q] * rj[q];
            }
            double angle = Math.acos(Math.max(-1.0, Math.min(1.0, 0.5 * (tr - 1.0))));
            mid[c] = 0.5 * (t.t(k) + t.t(k + 1));
            w[c++] = angle / dt;
        }
        double[] out = new double[Math.max(n, 0)];
        int s = 0;
        for (int g = 0; g < out.length; g++) {
            double tg = t0 + g * h;
            while (s + 1 < c && mid[s + 1] < tg) {
                s++;
            }
            if (c == 0) {
                out[g] = 0;
            } else if (s + 1 >= c || tg <= mid[s]) {
                out[g] = w[s];
            } else {
                double f = (tg - mid[s]) / (mid[s + 1] - mid[s]);
                out[g] = w[s] + f * (w[s + 1] - w[s]);
            }
        }
        return out;
    }
}
