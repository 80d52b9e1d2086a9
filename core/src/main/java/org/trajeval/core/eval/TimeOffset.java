package org.trajeval.core.eval;

/** Where the offset between the two clocks comes from. */
public enum TimeOffset {
    /** The given {@code tOffsetS} (default 0). */
    GIVEN,
    /** Estimated from the data ({@link org.trajeval.core.assoc.ClockOffset}), then refined on the ATE. */
    AUTO
}
