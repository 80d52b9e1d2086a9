package org.trajeval.core.stats;

/**
 * Mean and sample standard deviation of K repeated values m_1..m_K (the lesson's section 4):
 * mean = (1/K) sum m_k, sd = sqrt( (1/(K-1)) sum (m_k - mean)^2 ) (Bessel's correction, K-1).
 * The unit is the unit of the values. sd is NaN when K &lt; 2; both are NaN when K = 0.
 *
 * @param n number of values K
 * @param mean sample mean
 * @param sd sample standard deviation (K-1 in the denominator)
 */
public record SampleSummary(int n, double mean, double sd) {

    /** @throws IllegalArgumentException when n is negative */
    public SampleSummary {
        if (n < 0) {
            throw new IllegalArgumentException("n must be >= 0, got " + n);
        }
    }

    /** @return mean and sample standard deviation of {@code values} (two-pass, for accuracy) */
    public static SampleSummary of(double[] values) {
        int k = values.length;
        if (k == 0) {
            return new SampleSummary(0, Double.NaN, Double.NaN);
        }
        double sum = 0.0;
        for (double v : values) {
            sum += v;
        }
        double mean = sum / k;
        if (k < 2) {
            return new SampleSummary(k, mean, Double.NaN);
        }
        double sq = 0.0;
        for (double v : values) {
            double d = v - mean;
            sq += d * d;
        }
        return new SampleSummary(k, mean, Math.sqrt(sq / (k - 1)));
    }
}
