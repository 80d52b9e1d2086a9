package org.trajeval.core.io;

/** What a reader does with timestamps that are not strictly increasing. */
public enum TimestampOrder {
    /** Refuse a decreasing timestamp, naming the line (default). */
    REFUSE_UNSORTED,
    /** Sort the poses by timestamp ({@code --sort}); duplicates are still refused. */
    SORT
}
