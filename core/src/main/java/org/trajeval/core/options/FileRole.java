package org.trajeval.core.options;

/** Which of the two files of a pair. */
public enum FileRole {
    /** The reference (ground truth). */
    REFERENCE,
    /** The estimate. */
    ESTIMATE
}
