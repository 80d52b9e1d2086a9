package org.trajeval.pipeline.dir;

/** When a bundle in incoming/ counts as complete. */
public enum Completion {
    /** Only when its marker exists: {@code BUNDLE.done} beside a folder or zip, {@code NAME.done} for a pair. */
    MARKER,
    /** When its marker exists, or when it has been unchanged for the quiet time. */
    MARKER_OR_QUIET
}
