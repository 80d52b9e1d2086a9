package org.trajeval.pipeline;

import java.util.regex.Pattern;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Who and what a run is: the identity a report is filed under.
 *
 * @param runId the run's id, 1 to 128 characters of {@code A-Z a-z 0-9 . _ -}, not starting with a
 *     dot (it names the report file {@code reports/RUN_ID.json})
 * @param robotId the robot that recorded the run, or {@code null}
 * @param sequence the sequence (track, dataset) driven, or {@code null}
 * @param method the estimator that produced the estimate, or {@code null}
 * @param seed the estimator's random seed, or {@code null}
 * @param labels site, software version and free tags ({@link RunLabels#NONE} when none)
 */
public record RunMetadata(String runId, String robotId, String sequence, String method, Long seed,
        RunLabels labels) {
    private static final Pattern RUN_ID = Pattern.compile("[A-Za-z0-9_-][A-Za-z0-9._-]{0,127}");

    /** @throws InputException when the run id cannot name a file safely */
    public RunMetadata {
        if (runId == null || !RUN_ID.matcher(runId).matches()) {
            throw new InputException(null, 0, "run_id", InputProblem.INVALID_CONFIGURATION,
                    "run_id must be 1 to 128 characters of A-Z a-z 0-9 . _ - not starting with '.'", runId);
        }
        labels = labels == null ? RunLabels.NONE : labels;
    }

    /** Metadata without fleet labels. */
    public RunMetadata(String runId, String robotId, String sequence, String method, Long seed) {
        this(runId, robotId, sequence, method, seed, RunLabels.NONE);
    }

    /** @return metadata of a bare pair {@code NAME.gt.csv + NAME.est.csv}: only the run id (NAME) is known */
    public static RunMetadata ofName(String name) {
        return new RunMetadata(name, null, null, null, null);
    }
}
