package org.trajeval.core.metric;

/** Which trajectory the RPE pairs are chosen on (relevant for path-length deltas). */
public enum PairsFrom {
    /** Pairs chosen on the reference. */
    REFERENCE,
    /** Pairs chosen on the (aligned) estimate: evo's default. */
    ESTIMATE
}
