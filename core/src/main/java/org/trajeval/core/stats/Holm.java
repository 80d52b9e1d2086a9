package org.trajeval.core.stats;

import java.util.Arrays;

/**
 * Holm's step-down adjustment of m p-values for the family-wise error rate (Holm 1979, Scand. J.
 * Statist. 6:65-70; statsmodels' {@code multipletests(method="holm")}). With the raw p-values
 * sorted p_(1) &lt;= ... &lt;= p_(m): adj_(i) = max_{j &lt;= i} min(1, (m - j + 1) p_(j)). Rejecting
 * where adj &lt; alpha controls the probability of any false rejection at alpha, whatever the
 * dependence between the tests. Worked example: p = (0.01, 0.04, 0.03) gives (0.03, 0.06, 0.06).
 */
public final class Holm {
    private Holm() {
    }

    /**
     * @param p raw p-values in [0, 1], in any order
     * @return adjusted p-values, in the same order
     */
    public static double[] adjust(double[] p) {
        int m = p.length;
        Integer[] order = new Integer[m];
        for (int i = 0; i < m; i++) {
            if (!(p[i] >= 0.0 && p[i] <= 1.0)) {
                throw new IllegalArgumentException("a p-value must be in [0, 1], got " + p[i]);
            }
            order[i] = i;
        }
        Arrays.sort(order, (a, b) -> Double.compare(p[a], p[b]));
        double[] adj = new double[m];
        double running = 0.0;
        for (int j = 0; j < m; j++) {
            running = Math.max(running, Math.min(1.0, (m - j) * p[order[j]]));
            adj[order[j]] = running;
        }
        return adj;
    }
}
