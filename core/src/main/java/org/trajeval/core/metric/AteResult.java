package org.trajeval.core.metric;

import org.trajeval.core.stats.ErrorStatistics;

/**
 * Absolute trajectory error per associated pose and its statistics.
 *
 * @param transErrorsM |t_est,k - t_ref,k| per pose (m)
 * @param rotErrorsRad rotation angle of T_est,k^-1 T_ref,k per pose (rad)
 * @param trans statistics of the translation errors (m)
 * @param rot statistics of the rotation errors (rad)
 * @param full statistics of |E_k - I| (Frobenius norm, mixed units; evo's "full" relation), where
 *     E_k = T_est,k^-1 T_ref,k (evo's order)
 */
public record AteResult(double[] transErrorsM, double[] rotErrorsRad, ErrorStatistics trans, ErrorStatistics rot,
        ErrorStatistics full) {
}
