package org.trajeval.core.stats;

import java.util.Arrays;

/**
 * Friedman's rank test of "k methods perform alike" over n blocks (sequences), with the
 * Iman-Davenport F refinement (Demsar 2006, J. Mach. Learn. Res. 7:1-30, section 3.2.2).
 *
 * <p>Within each block the k values are ranked 1..k, rank 1 the best (lowest error, or highest
 * score), ties mid-ranked. R_j is the average rank of method j over the blocks. With the rank sums
 * S_j = n R_j and the tie correction C = 1 - sum_blocks sum_ties (t^3 - t) / (n k (k^2 - 1)) (as
 * SciPy's {@code friedmanchisquare}):
 * chi2_F = (12 / (n k (k+1)) sum_j S_j^2 - 3 n (k+1)) / C, with k-1 degrees of freedom, and
 * F_F = (n-1) chi2_F / (n(k-1) - chi2_F), with (k-1, (k-1)(n-1)) degrees of freedom. p-values are
 * upper tails (never 1 - cdf). When every block is tied throughout, chi2_F = 0 and p = 1; when
 * all blocks agree perfectly, F_F is infinite and its p is 0.
 */
public final class FriedmanTest {
    private FriedmanTest() {
    }

    /**
     * @param blocks n blocks
     * @param methods k methods
     * @param averageRanks R_j per method (1 = best)
     * @param chiSquare chi2_F (tie-corrected)
     * @param chiSquareP P(chi2_{k-1} &gt; chi2_F)
     * @param imanDavenport F_F (+infinity when the blocks agree perfectly)
     * @param imanDavenportP P(F_{k-1,(k-1)(n-1)} &gt; F_F)
     */
    public record Result(int blocks, int methods, double[] averageRanks, double chiSquare, double chiSquareP,
            double imanDavenport, double imanDavenportP) {
        /** Copies the ranks, so the record stays immutable. */
        public Result {
            averageRanks = averageRanks.clone();
        }

        @Override
        public double[] averageRanks() {
            return averageRanks.clone();
        }

        /** @return degrees of freedom of chi2_F: k - 1 */
        public int df() {
            return methods - 1;
        }

        /** @return denominator degrees of freedom of F_F: (k-1)(n-1) */
        public int dfDenominator() {
            return (methods - 1) * (blocks - 1);
        }
    }

    /**
     * @param values values[block][method], complete (no missing value), finite
     * @param lowerIsBetter true for errors (rank 1 = lowest), false for scores (rank 1 = highest)
     * @throws IllegalArgumentException with fewer than 2 blocks or 3 methods, or ragged or non-finite values
     */
    public static Result of(double[][] values, boolean lowerIsBetter) {
        int n = values.length;
        if (n < 2 || values[0].length < 3) {
            throw new IllegalArgumentException("the Friedman test needs at least 2 blocks and 3 methods, got "
                    + n + " blocks" + (n == 0 ? "" : " and " + values[0].length + " methods"));
        }
        int k = values[0].length;
        double[] rankSum = new double[k];
        double tieSum = 0.0;
        for (double[] row : values) {
            if (row.length != k) {
                throw new IllegalArgumentException("every block needs " + k + " values, got " + row.length);
            }
            double[] key = new double[k];
            for (int j = 0; j < k; j++) {
                if (!Double.isFinite(row[j])) {
                    throw new IllegalArgumentException("the Friedman test needs finite values, got " + row[j]);
                }
                key[j] = lowerIsBetter ? row[j] : -row[j];
            }
            double[] r = midRanks(key);
            for (int j = 0; j < k; j++) {
                rankSum[j] += r[j];
            }
            tieSum += tieTerm(key);
        }
        double[] avg = new double[k];
        double sumSq = 0.0;
        for (int j = 0; j < k; j++) {
            avg[j] = rankSum[j] / n;
            sumSq += rankSum[j] * rankSum[j];
        }
        double c = 1.0 - tieSum / (n * (double) k * (k * (double) k - 1.0));
        double chi2;
        if (c <= 0.0) {
            chi2 = 0.0;
        } else {
            chi2 = Math.max(0.0, (12.0 / (n * (double) k * (k + 1.0)) * sumSq - 3.0 * n * (k + 1.0)) / c);
        }
        double pChi = Quantiles.chiSquareUpperTail(chi2, k - 1.0);
        double denom = n * (k - 1.0) - chi2;
        double f = denom <= 0.0 ? Double.POSITIVE_INFINITY : (n - 1.0) * chi2 / denom;
        double pF = Quantiles.fUpperTail(f, k - 1.0, (k - 1.0) * (n - 1.0));
        return new Result(n, k, avg, chi2, pChi, f, pF);
    }

    /** @return mid-ranks 1..k of the values (ties share their mean rank) */
    static double[] midRanks(double[] v) {
        int k = v.length;
        Integer[] order = new Integer[k];
        for (int i = 0; i < k; i++) {
            order[i] = i;
        }
        Arrays.sort(order, (a, b) -> Double.compare(v[a], v[b]));
        double[] r = new double[k];
        int i = 0;
        while (i < k) {
            int j = i;
            while (j + 1 < k && v[order[j + 1]] == v[order[i]]) {
                j++;
            }
            for (int t = i; t <= j; t++) {
                r[order[t]] = (i + j + 2) / 2.0;
            }
            i = j + 1;
        }
        return r;
    }

    private static double tieTerm(double[] v) {
        double[] s = v.clone();
        Arrays.sort(s);
        double sum = 0.0;
        int i = 0;
        while (i < s.length) {
            int j = i;
            while (j + 1 < s.length && s[j + 1] == s[i]) {
                j++;
            }
            double t = j - i + 1;
            sum += t * t * t - t;
            i = j + 1;
        }
        return sum;
    }
}
