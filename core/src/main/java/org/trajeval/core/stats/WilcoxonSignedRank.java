package org.trajeval.core.stats;

import java.util.Arrays;

/**
 * Two-sided Wilcoxon signed-rank test of "the paired differences d_i are symmetric about 0".
 *
 * <p>Zero differences are dropped (Wilcoxon's original treatment) and counted in
 * {@link Result#zeros()}. The |d_i| of the remaining n differences are ranked 1..n, ties get
 * their mean rank; W+ is the sum of the ranks of the positive d_i, W- that of the negative ones,
 * W+ + W- = n(n+1)/2.
 *
 * <ul>
 *   <li>n &lt;= {@link #EXACT_MAX_N}: exact p-value, enumerating all 2^n sign assignments of the
 *       observed ranks (by dynamic programming over doubled ranks, so tied mid-ranks stay exact):
 *       p = min(1, 2 min(P(W+ &lt;= w), P(W+ &gt;= w))).</li>
 *   <li>n &gt; {@link #EXACT_MAX_N}: normal approximation with tie correction and continuity
 *       correction: E = n(n+1)/4, Var = n(n+1)(2n+1)/24 - sum_ties (t^3 - t)/48,
 *       z = (|W+ - E| - 1/2) / sqrt(Var), p = 2 Q(z) with the upper tail Q(z) = erfc(z/sqrt 2)/2
 *       (never 1 - Phi(z), which cancels in the tail).</li>
 * </ul>
 * Worked example: d = (1, -2, 3, 4, 5) gives ranks 1..5, W+ = 13, W- = 2; of the 32 sign
 * assignments 3 have W- &lt;= 2, so p = 2 * 3/32 = 0.1875.
 */
public final class WilcoxonSignedRank {
    /** Largest number of non-zero differences for which the exact distribution is used. */
    public static final int EXACT_MAX_N = 50;

    private WilcoxonSignedRank() {
    }

    /** How the p-value was obtained. */
    public enum Method {
        /** Exact distribution of W+ given the observed ranks. */
        EXACT,
        /** Normal approximation with tie and continuity correction. */
        NORMAL_APPROXIMATION,
        /** No non-zero differences: p = 1 by convention. */
        NO_NONZERO_DIFFERENCES
    }

    /**
     * @param n number of non-zero differences used
     * @param zeros number of zero differences dropped
     * @param wPlus W+, sum of ranks of positive differences
     * @param wMinus W-, sum of ranks of negative differences
     * @param pValue two-sided p-value
     * @param method how p was obtained
     */
    public record Result(int n, int zeros, double wPlus, double wMinus, double pValue, Method method) {
    }

    /** @return the test with the method chosen by n (exact up to {@link #EXACT_MAX_N}) */
    public static Result test(double[] differences) {
        Ranked r = rank(differences);
        if (r.n == 0) {
            return new Result(0, r.zeros, 0.0, 0.0, 1.0, Method.NO_NONZERO_DIFFERENCES);
        }
        return r.n <= EXACT_MAX_N ? exact(r) : normal(r);
    }

    /** @return the test with the normal approximation whatever n is (for cross-checks) */
    public static Result normalApproximation(double[] differences) {
        Ranked r = rank(differences);
        if (r.n == 0) {
            return new Result(0, r.zeros, 0.0, 0.0, 1.0, Method.NO_NONZERO_DIFFERENCES);
        }
        return normal(r);
    }

    private record Ranked(int n, int zeros, int[] doubledRanks, boolean[] positive, double tieTerm) {
        double wPlus() {
            long s = 0;
            for (int i = 0; i < n; i++) {
                if (positive[i]) {
                    s += doubledRanks[i];
                }
            }
            return s / 2.0;
        }
    }

    private static Ranked rank(double[] d) {
        for (double v : d) {
            if (!Double.isFinite(v)) {
                throw new IllegalArgumentException("Wilcoxon test needs finite differences, got " + v);
            }
        }
        double[] nz = Arrays.stream(d).filter(v -> v != 0.0).toArray();
        int n = nz.length;
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        Arrays.sort(order, (a, b) -> Double.compare(Math.abs(nz[a]), Math.abs(nz[b])));
        int[] doubled = new int[n];
        boolean[] pos = new boolean[n];
        double tieTerm = 0.0;
        int i = 0;
        while (i < n) {
            int j = i;
            while (j + 1 < n && Math.abs(nz[order[j + 1]]) == Math.abs(nz[order[i]])) {
                j++;
            }
            // ranks i+1 .. j+1 share the mean rank (i + j + 2) / 2; doubled: i + j + 2
            for (int k = i; k <= j; k++) {
                doubled[k] = i + j + 2;
                pos[k] = nz[order[k]] > 0;
            }
            double t = j - i + 1;
            tieTerm += t * t * t - t;
            i = j + 1;
        }
        return new Ranked(n, d.length - n, doubled, pos, tieTerm);
    }

    private static Result exact(Ranked r) {
        int total = 0;
        for (int v : r.doubledRanks) {
            total += v;
        }
        // counts[s] = number of sign assignments whose doubled W+ equals s
        double[] counts = new double[total + 1];
        counts[0] = 1.0;
        int reach = 0;
        for (int v : r.doubledRanks) {
            for (int s = reach; s >= 0; s--) {
                if (counts[s] != 0.0) {
                    counts[s + v] += counts[s];
                }
            }
            reach += v;
        }
        double all = Math.pow(2.0, r.n);
        int w2 = (int) Math.round(2.0 * r.wPlus());
        double below = 0.0;
        double above = 0.0;
        for (int s = 0; s <= total; s++) {
            if (s <= w2) {
                below += counts[s];
            }
            if (s >= w2) {
                above += counts[s];
            }
        }
        double p = Math.min(1.0, 2.0 * Math.min(below, above) / all);
        double wPlus = r.wPlus();
        return new Result(r.n, r.zeros, wPlus, r.n * (r.n + 1) / 2.0 - wPlus, p, Method.EXACT);
    }

    private static Result normal(Ranked r) {
        double n = r.n;
        double wPlus = r.wPlus();
        double mean = n * (n + 1) / 4.0;
        double var = n * (n + 1) * (2 * n + 1) / 24.0 - r.tieTerm / 48.0;
        double p;
        if (var <= 0.0) {
            p = 1.0;
        } else {
            double z = Math.max(0.0, Math.abs(wPlus - mean) - 0.5) / Math.sqrt(var);
            p = Math.min(1.0, 2.0 * Quantiles.normalUpperTail(z));
        }
        return new Result(r.n, r.zeros, wPlus, n * (n + 1) / 2.0 - wPlus, p, Method.NORMAL_APPROXIMATION);
    }
}
