package org.trajeval.store;

/**
 * How many runs one side of a gate has for a method on a pairing sequence (before pairing).
 *
 * @param method the method ({@code -} for runs without one)
 * @param sequence the pairing sequence ({@link GatePairing})
 * @param runs runs selected
 */
public record SideCell(String method, String sequence, long runs) {
}
