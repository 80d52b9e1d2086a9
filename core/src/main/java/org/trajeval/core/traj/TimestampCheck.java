package org.trajeval.core.traj;

/**
 * Checks shared by both trajectory types: finite values and non-decreasing timestamps (equal
 * stamps are allowed: readers refuse them unless told to keep them, as evo does).
 */
final class TimestampCheck {
    private TimestampCheck() {
    }

    static void requireSameLength(int n, double[]... columns) {
        for (double[] c : columns) {
            if (c.length != n) {
                throw new IllegalArgumentException("all columns must have " + n + " values, one has " + c.length);
            }
        }
    }

    static void requireNonDecreasing(double[] t) {
        requireNonDecreasing(t, t.length);
    }

    static void requireNonDecreasing(double[] t, int n) {
        for (int i = 0; i < n; i++) {
            if (!Double.isFinite(t[i])) {
                throw new IllegalArgumentException("timestamp " + i + " is not finite: " + t[i]);
            }
            if (i > 0 && !(t[i] >= t[i - 1])) {
                throw new IllegalArgumentException("timestamps must not decrease: t[" + i + "] = " + t[i]
                        + " s after t[" + (i - 1) + "] = " + t[i - 1] + " s");
            }
        }
    }

    static void requireFinite(String name, double[] v) {
        requireFinite(name, v, v.length);
    }

    static void requireFinite(String name, double[] v, int n) {
        for (int i = 0; i < n; i++) {
            if (!Double.isFinite(v[i])) {
                throw new IllegalArgumentException(name + "[" + i + "] is not finite: " + v[i]);
            }
        }
    }
}
