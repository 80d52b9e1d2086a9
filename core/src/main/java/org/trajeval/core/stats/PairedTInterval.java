package org.trajeval.core.stats;

/**
 * The lesson's section 7 interval for the mean of paired differences d_1..d_n:
 * d_bar +- t_{n-1, 1-alpha/2} * s_d / sqrt(n), with s_d^2 = (1/(n-1)) sum (d_i - d_bar)^2.
 * Assumes the d_i are independent and roughly normal; the unit is that of the d_i.
 */
public final class PairedTInterval {
    private PairedTInterval() {
    }

    /**
     * @param differences paired differences d_i (at least 2)
     * @param level confidence level 1 - alpha, e.g. 0.95
     * @throws IllegalArgumentException when fewer than 2 differences are given
     */
    public static Interval of(double[] differences, double level) {
        int n = differences.length;
        if (n < 2) {
            throw new IllegalArgumentException("a t-interval needs at least 2 paired differences, got " + n);
        }
        SampleSummary s = SampleSummary.of(differences);
        double t = Quantiles.studentUpper((1.0 - level) / 2.0, n - 1);
        double half = t * s.sd() / Math.sqrt(n);
        return new Interval(s.mean(), s.mean() - half, s.mean() + half, level);
    }
}
