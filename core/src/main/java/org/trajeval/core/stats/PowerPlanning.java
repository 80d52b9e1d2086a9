package org.trajeval.core.stats;

/**
 * Planning a paired comparison: how small a mean difference the suite can detect, and how many
 * sequences a given difference needs, from the standard deviation s_d of the per-sequence
 * differences. Two-sided test at level alpha = 1 - confidence, power 1 - beta (0.8 by default):
 * <pre>
 *   delta_min(n) = (t_{n-1, alpha/2} + t_{n-1, beta}) s_d / sqrt(n)      (t_{df, q}: upper q-quantile)
 *   n_needed(delta) = the smallest n &gt;= 2 with delta_min(n) &lt;= |delta|
 * </pre>
 * This is the usual t-quantile approximation of the paired t-test's power (the exact power
 * needs the noncentral t; the approximation is slightly optimistic at very small n). Worked
 * example: s_d = 1, n = 10, 95 %, 80 %: (2.262157 + 0.883330) / sqrt(10) = 0.994684.
 */
public final class PowerPlanning {
    /** Default power 1 - beta. */
    public static final double DEFAULT_POWER = 0.8;
    /** Largest number of sequences searched for n_needed. */
    public static final int MAX_SEQUENCES = 1_000_000;

    private PowerPlanning() {
    }

    /**
     * @param sd standard deviation s_d of the paired differences (unit of the metric), &gt;= 0
     * @param n number of sequences (&gt;= 2)
     * @param level confidence level 1 - alpha
     * @param power power 1 - beta, in (0.5, 1)
     * @return delta_min in the unit of s_d
     */
    public static double minimumDetectableDifference(double sd, int n, double level, double power) {
        check(sd, level, power);
        if (n < 2) {
            throw new IllegalArgumentException("planning needs at least 2 sequences, got " + n);
        }
        double q = (1.0 - level) / 2.0;
        return (Quantiles.studentUpper(q, n - 1) + Quantiles.studentUpper(1.0 - power, n - 1)) * sd / Math.sqrt(n);
    }

    /**
     * @param sd standard deviation s_d of the paired differences, &gt;= 0
     * @param difference the mean difference to detect (same unit), non-zero
     * @param level confidence level 1 - alpha
     * @param power power 1 - beta, in (0.5, 1)
     * @return n_needed, or -1 when more than {@link #MAX_SEQUENCES} would be needed
     */
    public static int sequencesNeeded(double sd, double difference, double level, double power) {
        check(sd, level, power);
        double target = Math.abs(difference);
        if (!(target > 0.0) || !Double.isFinite(target)) {
            throw new IllegalArgumentException("the difference to detect must be finite and non-zero, got "
                    + difference);
        }
        if (minimumDetectableDifference(sd, MAX_SEQUENCES, level, power) > target) {
            return -1;
        }
        int lo = 2;
        int hi = MAX_SEQUENCES;
        while (lo < hi) { // delta_min(n) decreases in n
            int mid = (lo + hi) >>> 1;
            if (minimumDetectableDifference(sd, mid, level, power) <= target) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        return lo;
    }

    private static void check(double sd, double level, double power) {
        if (!(sd >= 0.0) || !Double.isFinite(sd)) {
            throw new IllegalArgumentException("planning needs a finite standard deviation >= 0, got " + sd);
        }
        if (!(level > 0.0 && level < 1.0)) {
            throw new IllegalArgumentException("confidence level must be in (0, 1), got " + level);
        }
        if (!(power > 0.5 && power < 1.0)) {
            throw new IllegalArgumentException("power must be in (0.5, 1), got " + power);
        }
    }
}
