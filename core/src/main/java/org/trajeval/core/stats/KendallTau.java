package org.trajeval.core.stats;

/**
 * Kendall's rank correlation tau-b of two paired samples (x_i, y_i), with ties corrected as SciPy's
 * {@code scipy.stats.kendalltau(x, y)} (variant b):
 * <pre>
 *   tau_b = (C - D) / sqrt((n0 - n1) (n0 - n2))
 *   n0 = n (n - 1) / 2,  n1 = sum over tied groups of x of t (t - 1) / 2,  n2 likewise for y
 * </pre>
 * C counts the concordant pairs (x and y ordered alike), D the discordant ones; a pair tied in x or
 * in y is neither. Worked example: x = (1, 2, 3, 4, 5), y = (3, 4, 1, 2, 5) has C = 6, D = 4 of the
 * 10 pairs, tau_b = 0.2. Dimensionless, in [-1, 1]; NaN when one sample is constant or n &lt; 2.
 * Quadratic in n: meant for rankings of methods and per-level values, not for millions of points.
 */
public final class KendallTau {
    private KendallTau() {
    }

    /**
     * @param x first sample (finite values)
     * @param y second sample, paired with {@code x}
     * @return tau_b, or NaN when undefined
     * @throws IllegalArgumentException when the lengths differ
     */
    public static double tauB(double[] x, double[] y) {
        if (x.length != y.length) {
            throw new IllegalArgumentException("paired samples differ in length: " + x.length + " vs " + y.length);
        }
        int n = x.length;
        long concordant = 0;
        long discordant = 0;
        long tiedX = 0;
        long tiedY = 0;
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                int sx = Double.compare(x[i], x[j]);
                int sy = Double.compare(y[i], y[j]);
                if (sx == 0) {
                    tiedX++;
                }
                if (sy == 0) {
                    tiedY++;
                }
                if (sx != 0 && sy != 0) {
                    if (Integer.signum(sx) == Integer.signum(sy)) {
                        concordant++;
                    } else {
                        discordant++;
                    }
                }
            }
        }
        double n0 = n * (n - 1) / 2.0;
        double denominator = Math.sqrt((n0 - tiedX) * (n0 - tiedY));
        return denominator > 0.0 ? (concordant - discordant) / denominator : Double.NaN;
    }
}
