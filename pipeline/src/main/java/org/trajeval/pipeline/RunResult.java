package org.trajeval.pipeline;

import java.nio.file.Path;

/**
 * The result of processing one run.
 *
 * @param outcome reported, duplicate or failed
 * @param runId the run id, or {@code null} when it could not be read
 * @param version version of the run's report (1 for the first content, 2 for the first change, ...), 0 when failed
 * @param report the report file, or {@code null} when failed
 * @param failure why it failed, or {@code null}
 * @param firstSource for a duplicate: the source the earlier report came from; otherwise {@code null}
 */
public record RunResult(Outcome outcome, String runId, int version, Path report, RunFailure failure,
        String firstSource) {
    /** @return a failed result */
    public static RunResult failed(String runId, RunFailure failure) {
        return new RunResult(Outcome.FAILED, runId, 0, null, failure, null);
    }
}
