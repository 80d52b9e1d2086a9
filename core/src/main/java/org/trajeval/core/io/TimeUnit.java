package org.trajeval.core.io;

/** Unit of the timestamps in a file; converted to seconds on reading. */
public enum TimeUnit {
    /** Seconds. */
    S(1.0),
    /** Milliseconds. */
    MS(1e-3),
    /** Microseconds. */
    US(1e-6),
    /** Nanoseconds. */
    NS(1e-9);

    private final double seconds;

    TimeUnit(double seconds) {
        this.seconds = seconds;
    }

    /** @return the length of one unit in seconds */
    public double seconds() {
        return seconds;
    }
}
