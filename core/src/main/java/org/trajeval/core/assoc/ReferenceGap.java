package org.trajeval.core.assoc;

/**
 * A reference gap longer than the {@link MaxGap} limit, and the estimate poses dropped in it.
 *
 * @param startS time of the reference pose before the gap (s, reference clock)
 * @param endS time of the reference pose after the gap (s)
 * @param dropped estimate poses inside (startS, endS) that were dropped, >= 1
 */
public record ReferenceGap(double startS, double endS, int dropped) {
    /** @return endS - startS (s) */
    public double lengthS() {
        return endS - startS;
    }
}
