package org.trajeval.core.metric;

import java.util.function.IntToDoubleFunction;

/**
 * How much of the reference's time span the associated estimate covers. A run that lost
 * tracking half-way covers about half; its ATE over the poses it kept must not make it look
 * better than a run that kept tracking (evo issue #673; ETH3D and other leaderboards penalise it).
 *
 * <p>Uncovered time is the stretch before the first associated pose, the stretch after the last,
 * and every interval between consecutive associated poses longer than
 * {@value #GAP_FACTOR} times their mean spacing. Example: reference 0..100 s, estimate poses
 * every 0.1 s over 0..40 s and 60..100 s: the 20 s hole is uncovered, coverage 0.8, longest
 * stretch without an estimate 20 s.
 *
 * @param fraction covered share of the reference span, in [0, 1]
 * @param longestGapS longest stretch of the reference span without an associated estimate pose (s)
 * @param longestGapStartS where that stretch begins (s, reference clock)
 * @param uncoveredS total uncovered time (s)
 * @param referenceSpanS the reference's time span (s)
 */
public record Coverage(double fraction, double longestGapS, double longestGapStartS, double uncoveredS,
        double referenceSpanS) {
    /** An interval longer than this many mean spacings of the associated poses counts as uncovered. */
    public static final double GAP_FACTOR = 10.0;

    /**
     * @param stampS time of associated pose k on the reference clock (s), increasing
     * @param n number of associated poses
     * @param r0 first reference stamp (s)
     * @param r1 last reference stamp (s)
     */
    public static Coverage compute(IntToDoubleFunction stampS, int n, double r0, double r1) {
        double span = r1 - r0;
        if (n == 0) {
            return new Coverage(0.0, span, r0, span, span);
        }
        double first = stampS.applyAsDouble(0);
        double last = stampS.applyAsDouble(n - 1);
        double limit = n > 1 ? GAP_FACTOR * (last - first) / (n - 1) : Double.POSITIVE_INFINITY;
        double head = Math.max(0.0, first - r0);
        double tail = Math.max(0.0, r1 - last);
        double uncovered = head + tail;
        double longest = head;
        double longestStart = r0;
        if (tail > longest) {
            longest = tail;
            longestStart = last;
        }
        double prev = first;
        for (int k = 1; k < n; k++) {
            double t = stampS.applyAsDouble(k);
            double d = t - prev;
            if (d > limit) {
                uncovered += d;
            }
            if (d > longest) {
                longest = d;
                longestStart = prev;
            }
            prev = t;
        }
        double fraction = span > 0.0 ? Math.max(0.0, Math.min(1.0, 1.0 - uncovered / span)) : 1.0;
        return new Coverage(fraction, longest, longestStart, Math.min(uncovered, Math.max(span, 0.0)), span);
    }
}
