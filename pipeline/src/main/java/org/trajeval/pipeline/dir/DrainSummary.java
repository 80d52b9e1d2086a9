package org.trajeval.pipeline.dir;

/**
 * What a run of the directory service did.
 *
 * @param reported runs that got a report
 * @param duplicates runs already reported with the same content
 * @param failed bundles put in failed/
 */
public record DrainSummary(long reported, long duplicates, long failed) {
    /** @return 0 when nothing failed, 4 when some bundles were put in failed/ */
    public int exitCode() {
        return failed == 0 ? 0 : 4;
    }
}
