package org.trajeval.core.stats;

/**
 * A two-sided confidence interval [lower, upper] at level {@code level} (e.g. 0.95) around a
 * point estimate, in the unit of the estimate.
 *
 * @param estimate the point estimate
 * @param lower lower bound
 * @param upper upper bound
 * @param level confidence level 1 - alpha, in (0, 1)
 */
public record Interval(double estimate, double lower, double upper, double level) {

    /** @throws IllegalArgumentException when the level is not in (0, 1) or lower &gt; upper */
    public Interval {
        if (!(level > 0.0 && level < 1.0)) {
            throw new IllegalArgumentException("confidence level must be in (0, 1), got " + level);
        }
        if (lower > upper) {
            throw new IllegalArgumentException("interval lower bound " + lower + " exceeds upper bound " + upper);
        }
    }

    /** @return true when the interval contains {@code v} */
    public boolean contains(double v) {
        return lower <= v && v <= upper;
    }
}
