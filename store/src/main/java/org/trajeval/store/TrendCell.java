package org.trajeval.store;

/**
 * One slice's runs in one bucket, aggregated in the database.
 *
 * @param slice the slice's label (robot, site, ...), or null for runs without one
 * @param bucket the bucket's label: a day number since the epoch, or a software version
 * @param n number of successful runs with the metric
 * @param sum sum of the metric's values (metric unit)
 * @param sumSquares sum of the squared values (metric unit squared)
 * @param firstMs earliest recording time in the bucket (ms since the epoch)
 * @param lastMs latest recording time in the bucket (ms since the epoch)
 */
public record TrendCell(String slice, String bucket, long n, double sum, double sumSquares, long firstMs,
        long lastMs) {
    /** @return the mean, sum / n */
    public double mean() {
        return sum / n;
    }

    /** @return the sample variance (n - 1), NaN when n &lt; 2; from the sums, clamped at 0 against rounding */
    public double variance() {
        if (n < 2) {
            return Double.NaN;
        }
        return Math.max(0.0, (sumSquares - sum * sum / n) / (n - 1));
    }
}
