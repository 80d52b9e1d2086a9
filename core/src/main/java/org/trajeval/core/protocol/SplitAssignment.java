package org.trajeval.core.protocol;

import java.util.Objects;

/**
 * One row of a split table: sequence i, its session s(i) and split(i).
 *
 * @param sequenceId the sequence
 * @param sessionId the session (continuous traversal) the sequence was cut from
 * @param split the split
 */
public record SplitAssignment(String sequenceId, String sessionId, Split split) {
    /** @throws NullPointerException on a missing component */
    public SplitAssignment {
        Objects.requireNonNull(sequenceId, "sequenceId");
        Objects.requireNonNull(sessionId, "sessionId");
        Objects.requireNonNull(split, "split");
    }
}
