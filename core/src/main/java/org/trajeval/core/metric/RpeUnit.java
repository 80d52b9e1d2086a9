package org.trajeval.core.metric;

/** Unit of the RPE horizon delta. */
public enum RpeUnit {
    /** Seconds: j is the first sample with t_j >= t_i + delta (the lesson's rule). */
    SECONDS("s"),
    /** Frames: j = i + delta (evo's rule). */
    FRAMES("frames"),
    /** Metres travelled along the path (evo's rule). */
    METRES("m");

    private final String symbol;

    RpeUnit(String symbol) {
        this.symbol = symbol;
    }

    /** @return the unit as written in reports and on the command line: s, frames, m */
    public String symbol() {
        return symbol;
    }
}
