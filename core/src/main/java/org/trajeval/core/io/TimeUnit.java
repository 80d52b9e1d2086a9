package org.trajeval.core.io;

/** Unit of the timestamps in a file; converted to seconds on reading. */
public enum TimeUnit {
    /** Seconds. */
    S(1.0, 1.0),
    /** Milliseconds. */
    MS(1e-3, 1e3),
    /** Microseconds. */
    US(1e-6, 1e6),
    /** Nanoseconds. */
    NS(1e-9, 1e9);

    private final double seconds;
    private final double perSecond;

    TimeUnit(double seconds, double perSecond) {
        this.seconds = seconds;
        this.perSecond = perSecond;
    }

    /**
     * Converts a stamp to seconds: {@code stamp / perSecond()}, a correctly rounded division
     * (as evo's {@code np.divide(stamps, 1e9)} for nanoseconds; exact for seconds).
     *
     * @param stamp the time in this unit
     * @return the time (s)
     */
    public double toSeconds(double stamp) {
        return stamp / perSecond;
    }

    /** @return how many of this unit make one second (1, 1e3, 1e6, 1e9) */
    public double perSecond() {
        return perSecond;
    }

    /** @return the lower-case name used on the command line ("s", "ms", "us", "ns") */
    public String id() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }

    /** @return the length of one unit in seconds */
    public double seconds() {
        return seconds;
    }
}
