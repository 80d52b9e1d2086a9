package org.trajeval.core.stats;

import java.util.Arrays;

/**
 * Distribution-free confidence interval for a median from order statistics (Conover, Practical
 * Nonparametric Statistics, 3rd ed., section 3.2): with the n values sorted,
 * [x_(k), x_(n+1-k)] where k is the largest integer with P(B &le; k-1) &le; alpha/2 for
 * B ~ Binomial(n, 1/2); its achieved level is 1 - 2 P(B &le; k-1), at least the level asked.
 * When even k = 1 misses the level (n &lt; 6 at 95 %), the interval is the whole range [x_(1), x_(n)]
 * and the achieved level 1 - 2^(1-n) says how much less it holds. Worked example: n = 10 at 95 %:
 * P(B &le; 1) = 11/1024 = 0.0107 &le; 0.025 &lt; P(B &le; 2) = 56/1024, so k = 2, the interval
 * [x_(2), x_(9)] with achieved level 1 - 22/1024 = 0.9785. The unit is the values' unit.
 */
public final class MedianInterval {
    private MedianInterval() {
    }

    /**
     * @param median the sample median (mean of the two middle values for even n)
     * @param interval the interval [x_(k), x_(n+1-k)] at the level asked
     * @param achievedLevel 1 - 2 P(B &le; k-1)
     */
    public record Result(double median, Interval interval, double achievedLevel) {
    }

    /**
     * @param values at least one finite value
     * @param level confidence level in (0, 1)
     * @throws IllegalArgumentException on no values
     */
    public static Result of(double[] values, double level) {
        int n = values.length;
        if (n < 1) {
            throw new IllegalArgumentException("a median interval needs at least 1 value");
        }
        double[] s = values.clone();
        Arrays.sort(s);
        double median = n % 2 == 1 ? s[n / 2] : (s[n / 2 - 1] + s[n / 2]) / 2.0;
        double alpha = 1.0 - level;
        // P(B <= j) summed from the terms C(n, j) 2^-n, each built in log space (2^-n underflows for n > 1074)
        int k = 1;
        double logTerm = -n * Math.log(2.0);
        double cdf = Math.exp(logTerm); // P(B <= 0)
        for (int j = 1; j < n; j++) {
            logTerm += Math.log(n - j + 1) - Math.log(j);
            double next = cdf + Math.exp(logTerm); // P(B <= j)
            if (next > alpha / 2.0) {
                break;
            }
            cdf = next;
            k = j + 1;
        }
        double achieved = Math.max(0.0, 1.0 - 2.0 * cdf); // cdf = P(B <= k-1)
        return new Result(median, new Interval(median, s[k - 1], s[n - k], level), achieved);
    }
}
