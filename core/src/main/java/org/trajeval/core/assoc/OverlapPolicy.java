package org.trajeval.core.assoc;

/** What to do with estimate poses outside the reference's time span (interpolated association). */
public enum OverlapPolicy {
    /** Drop them and report how many were dropped (default). */
    CROP,
    /** Refuse the pair, naming the first pose outside. */
    STRICT
}
