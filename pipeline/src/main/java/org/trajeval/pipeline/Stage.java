package org.trajeval.pipeline;

/** Where in the processing of a run a failure happened (written into {@code <name>.error.json}). */
public enum Stage {
    /** Taking the bundle from incoming/ (or the event from the topic). */
    CLAIM,
    /** Opening the bundle: zip extraction, size limits, path checks. */
    UNPACK,
    /** Reading run.yaml or the event's fields. */
    MANIFEST,
    /** Reading and scoring the trajectories. */
    SCORE,
    /** Writing the report and the ledger entry. */
    REPORT
}
