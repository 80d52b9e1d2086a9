package org.trajeval.core.protocol;

/**
 * What counts as a failed run (lesson section 9: "What counts as a failure?"). A missing or
 * unreadable estimate, and an estimate the engine refuses (no overlap, too few poses), always
 * fail. The thresholds below are checked when set ({@code null}: not checked).
 *
 * @param minCoverage smallest accepted coverage, in [0, 1]: the fraction of the reference's time
 *     span covered by the estimate's time span
 * @param maxAteTransRmseM largest accepted ATE translation RMSE (m), &gt; 0
 * @param divergenceTransM a single ATE translation error above this (m, &gt; 0) means the run diverged
 * @param budget what a run over the budget is: a failure (default) or a warning
 * @param breakdownRate failure rate in (0, 1] at which a method has broken down at a factor level
 *     (stress sweeps; default {@link #DEFAULT_BREAKDOWN_RATE})
 */
public record FailureDefinition(Double minCoverage, Double maxAteTransRmseM, Double divergenceTransM,
        BudgetPolicy budget, double breakdownRate) {
    /** Default failure rate of a breakdown. */
    public static final double DEFAULT_BREAKDOWN_RATE = 0.5;

    /** No thresholds: only missing, unreadable or refused estimates fail. */
    public static final FailureDefinition NONE = new FailureDefinition(null, null, null);

    /** What a run over the budget is. */
    public enum BudgetPolicy {
        /** A failed run of reason {@code budget} (scores 0). */
        FAIL,
        /** A warning; the run keeps its status. */
        WARN
    }

    /** Thresholds only: budget violations fail, breakdown at 0.5. */
    public FailureDefinition(Double minCoverage, Double maxAteTransRmseM, Double divergenceTransM) {
        this(minCoverage, maxAteTransRmseM, divergenceTransM, BudgetPolicy.FAIL, DEFAULT_BREAKDOWN_RATE);
    }

    /** @throws IllegalArgumentException on a threshold out of range */
    public FailureDefinition {
        java.util.Objects.requireNonNull(budget, "budget");
        if (!(breakdownRate > 0.0 && breakdownRate <= 1.0)) {
            throw new IllegalArgumentException("breakdown_rate must be in (0, 1], got " + breakdownRate);
        }
        if (minCoverage != null && !(minCoverage >= 0.0 && minCoverage <= 1.0)) {
            throw new IllegalArgumentException("min_coverage must be in [0, 1], got " + minCoverage);
        }
        if (maxAteTransRmseM != null && !(maxAteTransRmseM > 0.0 && Double.isFinite(maxAteTransRmseM))) {
            throw new IllegalArgumentException("max_ate_trans_rmse_m must be > 0 (m), got " + maxAteTransRmseM);
        }
        if (divergenceTransM != null && !(divergenceTransM > 0.0 && Double.isFinite(divergenceTransM))) {
            throw new IllegalArgumentException("divergence_trans_m must be > 0 (m), got " + divergenceTransM);
        }
    }

    /** Why a run failed. */
    public enum Reason {
        /** The estimate file does not exist. */
        MISSING_ESTIMATE,
        /** The estimate file exists but could not be read or parsed. */
        UNREADABLE_ESTIMATE,
        /** The engine refused the pair (no overlap, too few poses, degenerate alignment). */
        EVALUATION_REFUSED,
        /** Coverage below {@code min_coverage}. */
        LOW_COVERAGE,
        /** ATE translation RMSE above {@code max_ate_trans_rmse_m}. */
        ATE_ABOVE_THRESHOLD,
        /** A translation error above {@code divergence_trans_m}, or a non-finite metric. */
        DIVERGED,
        /** The run needed more time or memory than the budget allows, or ran on another device. */
        BUDGET
    }

    /**
     * A failure verdict.
     *
     * @param reason the reason
     * @param detail one line for a person (what was measured against which threshold)
     */
    public record Failure(Reason reason, String detail) {
    }

    /**
     * Judges a run that the engine scored.
     *
     * @param coverage the run's coverage in [0, 1]
     * @param ateTransRmseM ATE translation RMSE (m)
     * @param ateTransMaxM largest ATE translation error (m)
     * @return the failure, or {@code null} when the run passes
     */
    public Failure judge(double coverage, double ateTransRmseM, double ateTransMaxM) {
        if (!Double.isFinite(ateTransRmseM) || !Double.isFinite(ateTransMaxM)) {
            return new Failure(Reason.DIVERGED, "ATE is not a finite number");
        }
        if (minCoverage != null && coverage < minCoverage) {
            return new Failure(Reason.LOW_COVERAGE, "coverage " + round(coverage) + " is below min_coverage "
                    + minCoverage);
        }
        if (divergenceTransM != null && ateTransMaxM > divergenceTransM) {
            return new Failure(Reason.DIVERGED, "largest ATE translation error " + round(ateTransMaxM)
                    + " m exceeds divergence_trans_m " + divergenceTransM + " m");
        }
        if (maxAteTransRmseM != null && ateTransRmseM > maxAteTransRmseM) {
            return new Failure(Reason.ATE_ABOVE_THRESHOLD, "ATE translation RMSE " + round(ateTransRmseM)
                    + " m exceeds max_ate_trans_rmse_m " + maxAteTransRmseM + " m");
        }
        return null;
    }

    private static String round(double v) {
        return String.format(java.util.Locale.ROOT, "%.4g", v);
    }
}
