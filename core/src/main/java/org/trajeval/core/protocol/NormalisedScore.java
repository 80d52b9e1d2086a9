package org.trajeval.core.protocol;

import java.util.List;
import java.util.Objects;

/**
 * The lesson's Proposition 3 score: s_j = max(0, 1 - m_j / c_j), S = 100 sum_j w_j s_j, with caps
 * c_j &gt; 0 and weights w_j &gt;= 0 summing to 1 (checked within {@link #WEIGHT_SUM_TOLERANCE}).
 * S lies in [0, 100], is non-increasing in every metric m_j (lower-is-better metrics) and is
 * Lipschitz in m_j with constant 100 w_j / c_j. A failed run (metric +infinity) scores 0.
 *
 * @param terms the scored metrics, each once
 */
public record NormalisedScore(List<Term> terms) {
    /** Largest accepted |sum w_j - 1|. */
    public static final double WEIGHT_SUM_TOLERANCE = 1e-9;

    /**
     * @param metric the metric m_j
     * @param cap c_j, in the metric's unit, &gt; 0: a value at or above the cap scores 0
     * @param weight w_j &gt;= 0
     */
    public record Term(RunMetric metric, double cap, double weight) {
        /** @throws IllegalArgumentException on a cap that is not &gt; 0 or a negative weight */
        public Term {
            Objects.requireNonNull(metric, "metric");
            if (!(cap > 0.0) || !Double.isFinite(cap)) {
                throw new IllegalArgumentException("cap of " + metric.key() + " must be a finite number > 0 ("
                        + metric.unit() + "), got " + cap);
            }
            if (!(weight >= 0.0) || !Double.isFinite(weight)) {
                throw new IllegalArgumentException("weight of " + metric.key() + " must be a finite number >= 0, got "
                        + weight);
            }
        }
    }

    /** @throws IllegalArgumentException on no terms, a repeated metric or weights not summing to 1 */
    public NormalisedScore {
        terms = List.copyOf(terms);
        if (terms.isEmpty()) {
            throw new IllegalArgumentException("the score needs at least one metric");
        }
        double sum = 0.0;
        for (int i = 0; i < terms.size(); i++) {
            sum += terms.get(i).weight();
            for (int j = 0; j < i; j++) {
                if (terms.get(i).metric() == terms.get(j).metric()) {
                    throw new IllegalArgumentException("score metric " + terms.get(i).metric().key()
                            + " appears twice");
                }
            }
        }
        if (Math.abs(sum - 1.0) > WEIGHT_SUM_TOLERANCE) {
            throw new IllegalArgumentException("score weights must sum to 1, got " + sum);
        }
    }

    /**
     * @param values m_j in the order of {@link #terms()}; NaN or +infinity counts as failed (s_j = 0)
     * @return S in [0, 100]
     */
    public double score(double[] values) {
        if (values.length != terms.size()) {
            throw new IllegalArgumentException("score needs " + terms.size() + " values, got " + values.length);
        }
        double s = 0.0;
        for (int j = 0; j < values.length; j++) {
            Term t = terms.get(j);
            double m = values[j];
            double sub = Double.isNaN(m) ? 0.0 : Math.max(0.0, 1.0 - m / t.cap());
            s += t.weight() * sub;
        }
        return 100.0 * s;
    }
}
