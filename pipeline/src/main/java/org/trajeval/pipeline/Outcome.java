package org.trajeval.pipeline;

/** What became of one run. */
public enum Outcome {
    /** A report was written (a new run, or a new version of a changed run). */
    REPORTED,
    /** The same run with the same content was reported before: nothing written. */
    DUPLICATE,
    /** The run was put aside with its reason. */
    FAILED;

    /** @return the lower-case name used in metrics and logs */
    public String label() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
