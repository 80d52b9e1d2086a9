package org.trajeval.core.protocol;

import java.io.Serializable;
import java.util.Objects;
import org.trajeval.core.report.SequencePlot;
import org.trajeval.core.report.SuiteReport.RunEntry;

/**
 * What one scored run gives the analysis: its report entry (status, failure reason, coverage,
 * metrics, score, the engine's report), the estimate's digest and the trace the HTML page draws.
 * Serialisable (Java serialisation, every number kept bit for bit), so a cluster can return it.
 *
 * @param entry the run's entry in {@code report.json} and {@code runs.csv}
 * @param sha256 SHA-256 of the estimate file, null when it does not exist
 * @param trace the aligned estimate and its error over time, null when the run was not evaluated
 */
public record RunResult(RunEntry entry, String sha256, SequencePlot.Trace trace) implements Serializable {
    private static final long serialVersionUID = 1L;

    /** @throws NullPointerException without an entry */
    public RunResult {
        Objects.requireNonNull(entry, "entry");
    }
}
