package org.trajeval.core.stats;

import org.apache.commons.math3.distribution.BetaDistribution;
import org.apache.commons.math3.distribution.NormalDistribution;
import org.apache.commons.math3.distribution.TDistribution;

/** Quantiles and tail probabilities of the distributions the intervals need (Commons Math stays here). */
final class Quantiles {
    private Quantiles() {
    }

    /** @return the p-quantile of Student's t with {@code df} degrees of freedom */
    static double student(double p, int df) {
        return new TDistribution(null, df).inverseCumulativeProbability(p);
    }

    /** @return the p-quantile of the standard normal distribution */
    static double normal(double p) {
        return new NormalDistribution(null, 0.0, 1.0).inverseCumulativeProbability(p);
    }

    /** @return P(Z &lt;= z) for the standard normal Z */
    static double normalCdf(double z) {
        return new NormalDistribution(null, 0.0, 1.0).cumulativeProbability(z);
    }

    /** @return the p-quantile of Beta(a, b) */
    static double beta(double p, double a, double b) {
        return new BetaDistribution(null, a, b).inverseCumulativeProbability(p);
    }
}
