package org.trajeval.core.stats;

/**
 * Null distribution of the Wilcoxon signed-rank statistic T+ for n untied, non-zero differences:
 * each of the 2^n sign assignments of the ranks 1..n is equally likely. Counts by dynamic
 * programming over the ranks (exact in doubles up to n = 50: counts stay below 2^53).
 */
final class SignedRankDistribution {
    private SignedRankDistribution() {
    }

    /** @return cdf[t] = P(T+ &lt;= t), t = 0 .. n(n+1)/2 */
    static double[] cdf(int n) {
        int total = n * (n + 1) / 2;
        double[] counts = new double[total + 1];
        counts[0] = 1.0;
        int reach = 0;
        for (int r = 1; r <= n; r++) {
            for (int s = reach; s >= 0; s--) {
                counts[s + r] += counts[s];
            }
            reach += r;
        }
        double all = Math.pow(2.0, n);
        double[] cdf = new double[total + 1];
        double run = 0.0;
        for (int t = 0; t <= total; t++) {
            run += counts[t];
            cdf[t] = run / all;
        }
        return cdf;
    }
}
