package org.trajeval.core.stats;

/**
 * Confidence interval for a proportion p = f / n (e.g. a failure rate), as the lesson's
 * section 7 asks ("report a binomial interval rather than only a percentage").
 */
public enum BinomialInterval {
    /**
     * Wilson score interval: (p + z^2/(2n) +- z sqrt(p(1-p)/n + z^2/(4n^2))) / (1 + z^2/n),
     * z = Phi^-1(1 - alpha/2). Good coverage at small n, never outside [0, 1].
     */
    WILSON,
    /**
     * Clopper-Pearson ("exact") interval: lower = Beta^-1(alpha/2; f, n-f+1) (0 when f = 0),
     * upper = Beta^-1(1-alpha/2; f+1, n-f) (1 when f = n), solved on the upper tail;
     * closed forms at f = 0 (upper 1 - (alpha/2)^(1/n)) and f = n (lower (alpha/2)^(1/n)). Conservative: coverage at least 1-alpha.
     */
    CLOPPER_PEARSON;

    /**
     * @param successes count f (0 &lt;= f &lt;= n)
     * @param trials count n (&gt; 0)
     * @param level confidence level 1 - alpha
     * @return interval around f / n
     * @throws IllegalArgumentException on counts out of range
     */
    public Interval of(int successes, int trials, double level) {
        if (trials <= 0 || successes < 0 || successes > trials) {
            throw new IllegalArgumentException("a binomial interval needs 0 <= f <= n and n > 0, got f = "
                    + successes + ", n = " + trials);
        }
        double alpha = 1.0 - level;
        double p = (double) successes / trials;
        return switch (this) {
            case WILSON -> {
                double z = Quantiles.normalUpper(alpha / 2.0);
                double z2 = z * z;
                double denom = 1.0 + z2 / trials;
                double centre = (p + z2 / (2.0 * trials)) / denom;
                double half = z * Math.sqrt(p * (1.0 - p) / trials + z2 / (4.0 * trials * (double) trials)) / denom;
                yield new Interval(p, Math.max(0.0, centre - half), Math.min(1.0, centre + half), level);
            }
            case CLOPPER_PEARSON -> {
                double lo = successes == 0 ? 0.0
                        : Quantiles.beta(alpha / 2.0, successes, trials - successes + 1.0);
                double hi = successes == trials ? 1.0
                        : Quantiles.betaUpper(alpha / 2.0, successes + 1.0, (double) trials - successes);
                yield new Interval(p, lo, hi, level);
            }
        };
    }
}
