package org.trajeval.figures;

import java.util.Arrays;

/**
 * Fewer points for long series, so a 10^6-pose figure stays a few hundred kB: every k-th point of
 * a path (first and last kept), and per bucket the minimum and maximum of a time series (peaks are
 * never lost: the drawn envelope is the data's).
 */
final class Decimate {
    /** Points kept of a path. */
    static final int PATH_POINTS = 20_000;
    /** Buckets of a time series (two points each): about two per pixel of the plot area at 1x, one at 2x. */
    static final int SERIES_BUCKETS = 1_000;

    private Decimate() {
    }

    /** @return indices 0, k, 2k, ..., n-1 with k chosen so that at most {@code max} remain */
    static int[] stride(int n, int max) {
        if (n <= max) {
            int[] all = new int[n];
            Arrays.setAll(all, i -> i);
            return all;
        }
        int k = (n + max - 2) / (max - 1);
        int m = (n - 1) / k + 1;
        int[] idx = new int[(n - 1) % k == 0 ? m : m + 1];
        for (int i = 0; i < m; i++) {
            idx[i] = i * k;
        }
        idx[idx.length - 1] = n - 1;
        return idx;
    }

    /** @return the values at the indices */
    static double[] pick(double[] v, int[] idx) {
        double[] out = new double[idx.length];
        for (int i = 0; i < idx.length; i++) {
            out[i] = v[idx[i]];
        }
        return out;
    }

    /**
     * @return {x, y}: per bucket of consecutive points, the minimum and the maximum of y in their
     *     order of occurrence; the series itself when it has at most 2 * buckets points
     */
    static double[][] minMax(double[] x, double[] y, int buckets) {
        int n = x.length;
        if (n <= 2 * buckets) {
            return new double[][] {x, y};
        }
        double[] ox = new double[2 * buckets];
        double[] oy = new double[2 * buckets];
        int k = 0;
        for (int b = 0; b < buckets; b++) {
            int from = (int) ((long) n * b / buckets);
            int to = (int) ((long) n * (b + 1) / buckets);
            int lo = from;
            int hi = from;
            for (int i = from; i < to; i++) {
                if (y[i] < y[lo] || !Double.isFinite(y[lo])) {
                    lo = i;
                }
                if (y[i] > y[hi] || !Double.isFinite(y[hi])) {
                    hi = i;
                }
            }
            int first = Math.min(lo, hi);
            int second = Math.max(lo, hi);
            ox[k] = x[first];
            oy[k++] = y[first];
            ox[k] = x[second];
            oy[k++] = y[second];
        }
        return new double[][] {ox, oy};
    }
}
