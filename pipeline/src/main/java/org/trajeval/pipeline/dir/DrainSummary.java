package org.trajeval.pipeline.dir;

/**
 * What a run of the directory service did.
 *
 * @param reported runs that got a report
 * @param duplicates runs already reported with the same content
 * @param failed bundles put in failed/
 * @param unfinished bundles left unprocessed because the service's own environment failed (disk full,
 *     read-only folder): those kept in processing/ and those still waiting in incoming/ when it stopped
 */
public record DrainSummary(long reported, long duplicates, long failed, long unfinished) {
    /** Exit code of a drain that left work unfinished. */
    public static final int UNFINISHED_EXIT = 7;
    /** Exit code of a drain that put bundles in failed/. */
    public static final int FAILED_EXIT = 4;

    /** A summary with nothing unfinished. */
    public DrainSummary(long reported, long duplicates, long failed) {
        this(reported, duplicates, failed, 0);
    }

    /** @return 0 when all is done, 7 when work was left unfinished, else 4 when some bundles were put in failed/ */
    public int exitCode() {
        return unfinished > 0 ? UNFINISHED_EXIT : failed > 0 ? FAILED_EXIT : 0;
    }
}
