package org.trajeval.core.stats;

import org.apache.commons.math3.analysis.solvers.BrentSolver;
import org.apache.commons.math3.special.Beta;
import org.apache.commons.math3.special.Erf;
import org.apache.commons.math3.special.Gamma;

/**
 * Quantiles and tail probabilities of the distributions the statistics need, to full double
 * accuracy (Commons Math stays here).
 *
 * <p>Two rules keep the last digits: a tail is evaluated directly, never as {@code 1 - cdf}
 * (the normal upper tail is erfc(z/sqrt 2)/2, the Beta upper tail I_{1-x}(b, a)); and a quantile
 * has its closed form where one exists (Beta(1, b), Beta(a, 1), t with 1 and 2 degrees of
 * freedom) and is otherwise found by Brent's method at machine tolerance, then polished by two
 * Newton steps on the smaller of the two tails. Commons Math's own inverses stop at an absolute
 * accuracy of 1e-9, which cost Clopper-Pearson bounds up to 1.6e-7 relative.
 */
final class Quantiles {
    private static final double SQRT2 = Math.sqrt(2.0);
    /** Continued-fraction convergence of the incomplete Beta and Gamma functions. */
    private static final double SERIES_EPS = 1e-15;
    private static final int SERIES_MAX = 1_000_000;

    private Quantiles() {
    }

    /** @return P(Z &gt; z) = erfc(z / sqrt 2) / 2 for the standard normal Z */
    static double normalUpperTail(double z) {
        return 0.5 * Erf.erfc(z / SQRT2);
    }

    /** @return the p-quantile of the standard normal distribution, p in (0, 1) */
    static double normal(double p) {
        if (p == 0.5) {
            return 0.0;
        }
        if (p > 0.5) {
            return normalUpper(1.0 - p); // 1 - p is exact for p >= 0.5
        }
        return -normalUpper(p);
    }

    /**
     * @param q upper tail probability in (0, 0.5]
     * @return z with P(Z &gt; z) = q (z &gt;= 0)
     */
    static double normalUpper(double q) {
        if (!(q > 0.0 && q <= 0.5)) {
            throw new IllegalArgumentException("normal upper tail must be in (0, 0.5], got " + q);
        }
        if (q == 0.5) {
            return 0.0;
        }
        double z = -Erf.erfInv(2.0 * q - 1.0) * SQRT2;
        if (!Double.isFinite(z)) {
            z = Math.sqrt(-2.0 * Math.log(q));
        }
        // Newton on h(z) = log Q(z) - log q (h' = -phi(z)/Q(z)): concave, so it converges from either side
        for (int i = 0; i < 8; i++) {
            double tail = normalUpperTail(z);
            double density = Math.exp(-0.5 * z * z) / Math.sqrt(2.0 * Math.PI);
            double step = (Math.log(tail) - Math.log(q)) * tail / density;
            z += step;
            if (Math.abs(step) <= 1e-17 * Math.abs(z)) {
                break;
            }
        }
        return z;
    }

    /**
     * Upper quantile of Student's t: t with P(T &gt; t) = q. Closed forms for df = 1
     * (t = cot(pi q)) and df = 2 (t = (1 - 2q) / sqrt(2q(1-q))); otherwise through the Beta
     * inverse, using P(|T| &gt; t) = I_{df/(df+t^2)}(df/2, 1/2).
     *
     * @param q upper tail probability in (0, 0.5]
     * @param df degrees of freedom (&gt;= 1)
     */
    static double studentUpper(double q, int df) {
        if (!(q > 0.0 && q <= 0.5) || df < 1) {
            throw new IllegalArgumentException("Student t upper quantile needs q in (0, 0.5] and df >= 1, got q = "
                    + q + ", df = " + df);
        }
        if (q == 0.5) {
            return 0.0;
        }
        if (df == 1) {
            return 1.0 / Math.tan(Math.PI * q);
        }
        if (df == 2) {
            return (1.0 - 2.0 * q) / Math.sqrt(2.0 * q * (1.0 - q));
        }
        double twoQ = 2.0 * q;
        if (twoQ < 0.5) {
            // x = df / (df + t^2) is the lower tail of Beta(df/2, 1/2) at 2q
            double x = beta(twoQ, df / 2.0, 0.5);
            return Math.sqrt(df * ((1.0 - x) / x));
        }
        // y = t^2 / (df + t^2) has the Beta(1/2, df/2) distribution, P(Y <= y) = 1 - 2q
        double y = beta(1.0 - twoQ, 0.5, df / 2.0);
        return Math.sqrt(df * (y / (1.0 - y)));
    }

    /** @return P(X &lt;= x) = I_x(a, b) for X ~ Beta(a, b) */
    static double betaCdf(double x, double a, double b) {
        if (x <= 0.0) {
            return 0.0;
        }
        if (x >= 1.0) {
            return 1.0;
        }
        return Beta.regularizedBeta(x, a, b, SERIES_EPS, SERIES_MAX);
    }

    /** @return P(X &gt; x) = I_{1-x}(b, a) for X ~ Beta(a, b), without cancellation */
    static double betaUpperTail(double x, double a, double b) {
        return betaCdf(1.0 - x, b, a);
    }

    /**
     * The p-quantile of Beta(a, b): x with I_x(a, b) = p. Closed forms: a = 1 gives
     * 1 - (1-p)^(1/b), b = 1 gives p^(1/a); otherwise Brent's method then Newton.
     *
     * @param p probability in [0, 1]
     * @param a first shape (&gt; 0)
     * @param b second shape (&gt; 0)
     */
    static double beta(double p, double a, double b) {
        return p <= 0.5 ? betaInverse(p, true, a, b) : betaInverse(1.0 - p, false, a, b);
    }

    /**
     * The upper quantile of Beta(a, b): x with P(X &gt; x) = I_{1-x}(b, a) = q, solved on the upper
     * tail itself (so q = alpha/2 keeps every digit). Closed forms: a = 1 gives 1 - q^(1/b), b = 1
     * gives (1-q)^(1/a).
     *
     * @param q upper tail probability in [0, 1]
     * @param a first shape (&gt; 0)
     * @param b second shape (&gt; 0)
     */
    static double betaUpper(double q, double a, double b) {
        return betaInverse(q, false, a, b);
    }

    private static double betaInverse(double tail, boolean lower, double a, double b) {
        if (!(tail >= 0.0 && tail <= 1.0) || !(a > 0.0) || !(b > 0.0)) {
            throw new IllegalArgumentException("Beta quantile needs a tail probability in [0, 1] and a, b > 0, got "
                    + tail + ", a = " + a + ", b = " + b);
        }
        if (tail == 0.0) {
            return lower ? 0.0 : 1.0;
        }
        if (tail == 1.0) {
            return lower ? 1.0 : 0.0;
        }
        if (a == 1.0) {
            return lower ? -Math.expm1(Math.log1p(-tail) / b) : -Math.expm1(Math.log(tail) / b);
        }
        if (b == 1.0) {
            return lower ? Math.exp(Math.log(tail) / a) : Math.exp(Math.log1p(-tail) / a);
        }
        // g(x) = (tail at x) - target, increasing in x for both tails
        org.apache.commons.math3.analysis.UnivariateFunction g = x -> lower
                ? betaCdf(x, a, b) - tail : tail - betaUpperTail(x, a, b);
        double x = new BrentSolver(1e-15, 1e-300, 0.0).solve(10_000, g, 0.0, 1.0, a / (a + b));
        double logNorm = Beta.logBeta(a, b);
        for (int i = 0; i < 2 && x > 0.0 && x < 1.0; i++) {
            double density = Math.exp((a - 1.0) * Math.log(x) + (b - 1.0) * Math.log1p(-x) - logNorm);
            double next = x - g.value(x) / density;
            if (!(next > 0.0 && next < 1.0)) {
                break;
            }
            x = next;
        }
        return x;
    }

    /** @return P(X &gt; x) for X chi-square with {@code df} degrees of freedom: Q(df/2, x/2) */
    static double chiSquareUpperTail(double x, double df) {
        if (x <= 0.0) {
            return 1.0;
        }
        return Gamma.regularizedGammaQ(df / 2.0, x / 2.0, SERIES_EPS, SERIES_MAX);
    }

    /** @return P(F &gt; f) for F with (d1, d2) degrees of freedom: I_{d2/(d2 + d1 f)}(d2/2, d1/2) */
    static double fUpperTail(double f, double d1, double d2) {
        if (f <= 0.0) {
            return 1.0;
        }
        if (f == Double.POSITIVE_INFINITY) {
            return 0.0;
        }
        return betaCdf(d2 / (d2 + d1 * f), d2 / 2.0, d1 / 2.0);
    }
}
