package org.trajeval.core.metric;

import org.trajeval.core.stats.ErrorStatistics;

/**
 * Relative pose error over index pairs.
 *
 * @param first index i of each pair
 * @param second index j of each pair
 * @param transErrorsM |trans(E_ij)| per pair (m)
 * @param rotErrorsRad rotation angle of E_ij per pair (rad)
 * @param trans statistics of the translation errors (m)
 * @param rot statistics of the rotation errors (rad)
 * @param full statistics of |E_ij - I| (Frobenius norm, mixed units; evo's "full" relation)
 * @param meanHorizonS mean of t_j - t_i over the pairs (s); NaN without pairs
 * @param meanHorizonM mean reference path length from i to j over the pairs (m); NaN without pairs
 */
public record RpeResult(int[] first, int[] second, double[] transErrorsM, double[] rotErrorsRad,
        ErrorStatistics trans, ErrorStatistics rot, ErrorStatistics full, double meanHorizonS, double meanHorizonM) {

    /** @return number of pairs */
    public int pairs() {
        return first.length;
    }
}
