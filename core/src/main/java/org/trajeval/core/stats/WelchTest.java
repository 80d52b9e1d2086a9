package org.trajeval.core.stats;

import org.apache.commons.math3.distribution.TDistribution;

/**
 * Welch's unequal-variance t-test of two independent samples given by their summaries, one-sided:
 * H1 mean_1 &gt; mean_2. t = (m1 - m2) / sqrt(v1/n1 + v2/n2) with the Welch-Satterthwaite degrees of
 * freedom df = (v1/n1 + v2/n2)^2 / ((v1/n1)^2/(n1-1) + (v2/n2)^2/(n2-1)); p = P(T_df &gt;= t), taken
 * as the survival function through the symmetry P(T &gt;= t) = P(T &lt;= -t), never 1 - cdf. As SciPy's
 * {@code ttest_ind(a, b, equal_var=False, alternative='greater')}.
 *
 * <p>Example: n1 = n2 = 10, m1 = 1.2, m2 = 1.0, v1 = v2 = 0.04 gives t = 2.236, df = 18, p = 0.0191.
 */
public final class WelchTest {
    private WelchTest() {
    }

    /**
     * @param n1 size of sample 1 (at least 2)
     * @param mean1 its mean
     * @param var1 its sample variance (n - 1)
     * @param n2 size of sample 2 (at least 2)
     * @param mean2 its mean
     * @param var2 its sample variance (n - 1)
     * @return the one-sided p-value of H1 mean1 &gt; mean2; 1 or 0 when both variances are 0 (by the sign
     *     of the difference; 1 when equal)
     */
    public static double greater(long n1, double mean1, double var1, long n2, double mean2, double var2) {
        if (n1 < 2 || n2 < 2) {
            throw new IllegalArgumentException("Welch's test needs at least 2 values per sample, got " + n1 + " and "
                    + n2);
        }
        double a = var1 / n1;
        double b = var2 / n2;
        double se2 = a + b;
        if (se2 == 0.0) {
            return mean1 > mean2 ? 0.0 : 1.0;
        }
        double t = (mean1 - mean2) / Math.sqrt(se2);
        double df = se2 * se2 / (a * a / (n1 - 1) + b * b / (n2 - 1));
        return new TDistribution(null, df).cumulativeProbability(-t);
    }

    /**
     * The t-interval of a mean from a summary: mean +- t_{n-1, 1-alpha/2} sd / sqrt(n).
     *
     * @param n number of values (at least 2)
     * @param mean the mean
     * @param sd the sample standard deviation (n - 1)
     * @param level confidence level in (0, 1)
     */
    public static Interval meanInterval(long n, double mean, double sd, double level) {
        if (n < 2) {
            throw new IllegalArgumentException("a t-interval needs at least 2 values, got " + n);
        }
        double half = new TDistribution(null, n - 1).inverseCumulativeProbability(1.0 - (1.0 - level) / 2.0) * sd
                / Math.sqrt(n);
        return new Interval(mean, mean - half, mean + half, level);
    }
}
