package org.trajeval.core.metric;

/**
 * RPE settings.
 *
 * @param delta horizon in {@code unit} (> 0; whole number for frames)
 * @param unit seconds, frames or metres
 * @param selection consecutive or all pairs
 * @param pairsFrom the trajectory the pairs are chosen on
 */
public record RpeOptions(double delta, RpeUnit unit, PairSelection selection, PairsFrom pairsFrom) {
}
