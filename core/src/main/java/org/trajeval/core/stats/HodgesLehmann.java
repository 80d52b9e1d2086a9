package org.trajeval.core.stats;

import java.util.Arrays;

/**
 * Hodges-Lehmann estimate of the centre of paired differences d_1..d_n, with its distribution-free
 * confidence interval (Hollander and Wolfe, Nonparametric Statistical Methods, 3rd ed., section 3.2).
 *
 * <p>The estimate is the median of the M = n(n+1)/2 Walsh averages (d_i + d_j)/2, i &lt;= j (zeros
 * included: it estimates the median difference, not only among non-zero ones). The interval is
 * [W_(k), W_(M+1-k)] of the sorted Walsh averages:
 * <ul>
 *   <li>exact, n &lt;= {@link WilcoxonSignedRank#EXACT_MAX_N}: k = 1 + max{c : P(T &lt;= c) &lt;= alpha/2}
 *       under the untied signed-rank distribution of n; its achieved level 1 - 2 P(T &lt;= k-1) is at
 *       least 1 - alpha and is reported. When even P(T = 0) = 2^-n exceeds alpha/2 (n &lt;= 5 at
 *       95 %), k = 1: the interval is [min, max] with achieved level 1 - 2^(1-n), below the one asked.</li>
 *   <li>asymptotic, larger n: k = round(M/2 - z_{1-alpha/2} sqrt(n(n+1)(2n+1)/24)), at least 1.</li>
 * </ul>
 * With ties among the d_i the exact level is that of the untied distribution (approximate).
 * Worked example: d = (1, 2, 3): Walsh averages 1, 1.5, 2, 2, 2.5, 3, median 2.
 */
public final class HodgesLehmann {
    private HodgesLehmann() {
    }

    /** How the interval was obtained. */
    public enum Method {
        /** Order statistics from the exact signed-rank distribution. */
        EXACT,
        /** Order statistics from the normal approximation of the signed-rank distribution. */
        ASYMPTOTIC
    }

    /**
     * @param estimate median of the Walsh averages (unit of the d_i)
     * @param interval [W_(k), W_(M+1-k)] around it, at the requested level
     * @param achievedLevel coverage the discrete exact interval attains (the requested level when asymptotic)
     * @param method exact or asymptotic
     */
    public record Result(double estimate, Interval interval, double achievedLevel, Method method) {
    }

    /**
     * @param d paired differences (at least 1, finite)
     * @param level confidence level 1 - alpha
     * @throws IllegalArgumentException on no or non-finite differences
     */
    public static Result of(double[] d, double level) {
        int n = d.length;
        if (n < 1) {
            throw new IllegalArgumentException("a Hodges-Lehmann estimate needs at least 1 difference");
        }
        int m = n * (n + 1) / 2;
        double[] walsh = new double[m];
        int w = 0;
        for (int i = 0; i < n; i++) {
            if (!Double.isFinite(d[i])) {
                throw new IllegalArgumentException("Hodges-Lehmann needs finite differences, got " + d[i]);
            }
            for (int j = i; j < n; j++) {
                walsh[w++] = 0.5 * d[i] + 0.5 * d[j];
            }
        }
        Arrays.sort(walsh);
        double median = (m % 2 == 1) ? walsh[m / 2] : 0.5 * walsh[m / 2 - 1] + 0.5 * walsh[m / 2];
        double alpha = 1.0 - level;
        int k;
        double achieved;
        Method method;
        if (n <= WilcoxonSignedRank.EXACT_MAX_N) {
            double[] cdf = SignedRankDistribution.cdf(n);
            int c = -1;
            while (c + 1 < cdf.length && cdf[c + 1] <= alpha / 2.0) {
                c++;
            }
            k = Math.max(1, c + 1);
            // P(W_(k) <= centre <= W_(M+1-k)) = 1 - 2 P(T <= k-1); below the level only when k = 1 is forced
            achieved = 1.0 - 2.0 * cdf[k - 1];
            method = Method.EXACT;
        } else {
            double sd = Math.sqrt(n * (n + 1.0) * (2.0 * n + 1.0) / 24.0);
            k = (int) Math.max(1, Math.round(m / 2.0 - Quantiles.normalUpper(alpha / 2.0) * sd));
            achieved = level;
            method = Method.ASYMPTOTIC;
        }
        Interval ci = new Interval(median, walsh[k - 1], walsh[m - k], level);
        return new Result(median, ci, achieved, method);
    }
}
