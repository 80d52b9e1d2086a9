package org.trajeval.core.metric;

/** Which index pairs (i, j) an RPE uses. */
public enum PairSelection {
    /** The lesson's rule in seconds (every i), evo's consecutive rule in frames and metres. */
    CONSECUTIVE,
    /** Every start index i with its matching j (evo's --all_pairs). */
    ALL_PAIRS
}
