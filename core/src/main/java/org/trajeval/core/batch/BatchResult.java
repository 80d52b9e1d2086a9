package org.trajeval.core.batch;

import java.util.Objects;
import org.trajeval.core.protocol.RunMetric;
import org.trajeval.core.report.EvaluationReport;

/**
 * What scoring one {@link BatchPair} gave: its summary row. A pair that could not be scored is a
 * failed row with the reason, never an exception: {@code failureReason} is the
 * {@link org.trajeval.core.InputProblem} in lower case for bad input ({@code no_overlap},
 * {@code not_finite}, ...), {@value #WRITE_FAILED} when its report could not be written, or
 * {@value #INTERNAL_ERROR} for a bug.
 *
 * @param pair the row
 * @param status {@value #OK} or {@value #FAILED}
 * @param failureReason why it failed, or {@code null}
 * @param failureDetail the one-line message (file, line, what was expected, what was found), or {@code null}
 * @param metrics the values of {@link RunMetric#values()} in that order (m, rad, %; NaN when absent or failed)
 * @param coverage the report's coverage fraction of the reference span (NaN when failed)
 * @param reportFile the report's file name in the report folder, or {@code null} when failed
 */
public record BatchResult(BatchPair pair, String status, String failureReason, String failureDetail,
        double[] metrics, double coverage, String reportFile) {
    /** Status of a scored pair. */
    public static final String OK = "ok";
    /** Status of a pair that could not be scored. */
    public static final String FAILED = "failed";
    /** Failure reason of an unexpected error (a bug: the detail names the exception). */
    public static final String INTERNAL_ERROR = "internal_error";
    /** Failure reason of a report the file system did not take (full, read-only): the detail names the OS error. */
    public static final String WRITE_FAILED = "write_failed";

    /** @throws IllegalArgumentException on an unknown status or metrics of the wrong length */
    public BatchResult {
        Objects.requireNonNull(pair, "pair");
        if (!OK.equals(status) && !FAILED.equals(status)) {
            throw new IllegalArgumentException("status must be ok or failed, got " + status);
        }
        if (metrics.length != RunMetric.values().length) {
            throw new IllegalArgumentException("one value per RunMetric expected, got " + metrics.length);
        }
        metrics = metrics.clone();
    }

    /** @return the row of a scored pair, whose report was written as {@code reportFile} */
    public static BatchResult scored(BatchPair pair, EvaluationReport report, String reportFile) {
        RunMetric[] all = RunMetric.values();
        double[] m = new double[all.length];
        for (int k = 0; k < all.length; k++) {
            m[k] = all[k].of(report);
        }
        double cov = report.coverage() == null ? Double.NaN : report.coverage().fraction();
        return new BatchResult(pair, OK, null, null, m, cov, reportFile);
    }

    /** @return the row of a pair that could not be scored */
    public static BatchResult failed(BatchPair pair, String reason, String detail) {
        double[] m = new double[RunMetric.values().length];
        java.util.Arrays.fill(m, Double.NaN);
        return new BatchResult(pair, FAILED, reason, detail, m, Double.NaN, null);
    }

    @Override
    public double[] metrics() {
        return metrics.clone();
    }

    /** @return the value of one metric (NaN when absent) */
    public double metric(RunMetric m) {
        return metrics[m.ordinal()];
    }

    /** @return whether the pair was scored */
    public boolean ok() {
        return OK.equals(status);
    }

    /** @return whether the pair failed on an unexpected error (a bug) rather than on its input */
    public boolean internalError() {
        return INTERNAL_ERROR.equals(failureReason);
    }
}
