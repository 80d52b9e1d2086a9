package org.trajeval.core.report;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;

/**
 * The one report of one (reference, estimate) evaluation: what {@code trajeval eval --json}
 * prints, one run entry of a suite report, and one pipeline report. Versioned by
 * {@link #SCHEMA} / {@link #SCHEMA_VERSION}; the JSON Schema is {@code docs/report.schema.json}.
 * Units are in the key names (m, rad, s).
 *
 * @param schema always {@link #SCHEMA}
 * @param schemaVersion always {@link #SCHEMA_VERSION}
 * @param version trajeval version that wrote the report
 * @param convention convention preset the options started from (lesson, evo, kitti)
 * @param inputs the two input files
 * @param association how poses were paired in time
 * @param alignment the fitted alignment
 * @param ate absolute trajectory error
 * @param rpe relative pose error
 * @param drift length-normalised drift, or {@code null} when not asked
 * @param extra per-axis, heading and speed errors ({@code extra_metrics}), or {@code null}
 * @param timeBase s, or frames when both inputs are stamped by index (KITTI without times files):
 *     then every *_s value and every time in the report counts frames
 * @param coverage share of the reference's time span the associated estimate covers
 * @param warnings what a careful user should know about these numbers (degenerate alignment,
 *     poses dropped in reference gaps, ...), machine-readable
 */
@JsonPropertyOrder({"schema", "schema_version", "version", "convention", "time_base", "inputs", "association",
    "coverage",
    "alignment", "ate", "rpe", "drift", "extra", "warnings"})
@JsonInclude(JsonInclude.Include.NON_NULL)
public record EvaluationReport(
        @JsonProperty("schema") String schema,
        @JsonProperty("schema_version") int schemaVersion,
        @JsonProperty("version") String version,
        @JsonProperty("convention") String convention,
        @JsonProperty("inputs") Inputs inputs,
        @JsonProperty("association") AssociationInfo association,
        @JsonProperty("alignment") AlignmentInfo alignment,
        @JsonProperty("ate") Ate ate,
        @JsonProperty("rpe") Rpe rpe,
        @JsonProperty("drift") Drift drift,
        @JsonProperty("coverage") CoverageInfo coverage,
        @JsonProperty("warnings") java.util.List<Warning> warnings,
        @JsonProperty("time_base") String timeBase,
        @JsonProperty("extra") Extra extra) implements java.io.Serializable {

    /** @return a copy with another association section */
    public EvaluationReport withAssociation(AssociationInfo a) {
        return new EvaluationReport(schema, schemaVersion, version, convention, inputs, a, alignment, ate, rpe, drift,
                coverage, warnings, timeBase, extra);
    }

    /** @return a copy with one more warning at the end */
    public EvaluationReport withWarning(Warning w) {
        java.util.List<Warning> more = new java.util.ArrayList<>(warnings);
        more.add(w);
        return new EvaluationReport(schema, schemaVersion, version, convention, inputs, association, alignment, ate,
                rpe, drift, coverage, more, timeBase, extra);
    }

    /** @throws NullPointerException never; null warnings (older reports) read as none */
    public EvaluationReport {
        warnings = warnings == null ? java.util.List.of() : java.util.List.copyOf(warnings);
    }

    /** Name of the report schema. */
    public static final String SCHEMA = "trajeval.evaluation";
    /** Version of the report schema; bumped on any incompatible change. */
    public static final int SCHEMA_VERSION = 1;

    /** @return this report with other inputs (trajectories given as arrays through the Java API) */
    public EvaluationReport withInputs(Inputs other) {
        return new EvaluationReport(schema, schemaVersion, version, convention, other, association, alignment, ate,
                rpe, drift, coverage, warnings, timeBase, extra);
    }

    /**
     * @param reference the reference (ground truth) input
     * @param estimate the estimate input
     */
    @JsonPropertyOrder({"reference", "estimate"})
    public record Inputs(@JsonProperty("reference") InputInfo reference,
            @JsonProperty("estimate") InputInfo estimate) implements java.io.Serializable {
    }

    /**
     * @param path the file as given
     * @param format the format read (csv, tum, kitti, euroc)
     * @param formatReason why that format was chosen (given, or what auto-detection saw)
     * @param poses number of poses read
     * @param sha256 SHA-256 of the file's bytes, lower-case hex
     */
    @JsonPropertyOrder({"path", "format", "format_reason", "poses", "sha256"})
    public record InputInfo(@JsonProperty("path") String path, @JsonProperty("format") String format,
            @JsonProperty("format_reason") String formatReason, @JsonProperty("poses") int poses,
            @JsonProperty("sha256") String sha256) implements java.io.Serializable {
    }

    /**
     * @param method interpolate, nearest or nearest_interpolated
     * @param matched number of associated pose pairs
     * @param dropped estimate poses that were not associated (outside the overlap or beyond max diff)
     * @param droppedReference reference poses not associated (nearest association only; 0 otherwise)
     * @param maxDiffS max timestamp difference (s) for nearest association
     * @param tOffsetS offset added to the estimate stamps (s)
     * @param overlap crop or strict
     * @param maxGapS largest sampling gap h of the reference over the matched span (s)
     * @param aMaxMps2 largest acceleration norm of the reference over the matched span, estimated by
     *     second divided differences (m/s^2); null for nearest association
     * @param interpErrorBoundM the lesson's Proposition 2 bound A_max h^2 / 8 (m); null for nearest association
     * @param gapLimitS longest reference gap interpolation may bridge (s); null for nearest association
     * @param droppedInGaps estimate poses dropped inside longer reference gaps (part of {@code dropped})
     * @param gaps those gaps, in time order (at most {@link #MAX_GAPS_LISTED})
     * @param tOffsetAuto how the offset was estimated ({@code --t-offset auto}), or null when given
     */
    @JsonPropertyOrder({"method", "matched", "dropped", "dropped_reference", "max_diff_s", "t_offset_s", "overlap",
        "max_gap_s", "a_max_mps2", "interp_error_bound_m", "gap_limit_s", "dropped_in_gaps", "gaps", "t_offset_auto"})
    public record AssociationInfo(@JsonProperty("method") String method, @JsonProperty("matched") int matched,
            @JsonProperty("dropped") int dropped, @JsonProperty("dropped_reference") int droppedReference,
            @JsonProperty("max_diff_s") double maxDiffS, @JsonProperty("t_offset_s") double tOffsetS,
            @JsonProperty("overlap") String overlap, @JsonProperty("max_gap_s") double maxGapS,
            @JsonProperty("a_max_mps2") Double aMaxMps2,
            @JsonProperty("interp_error_bound_m") Double interpErrorBoundM,
            @JsonProperty("gap_limit_s") Double gapLimitS, @JsonProperty("dropped_in_gaps") int droppedInGaps,
            @JsonProperty("gaps") java.util.List<Gap> gaps,
            @JsonProperty("t_offset_auto") OffsetEstimate tOffsetAuto) implements java.io.Serializable {
        /** Most gaps listed in a report (all are counted). */
        public static final int MAX_GAPS_LISTED = 100;

        /** @return a copy with the offset used and how it was estimated */
        public AssociationInfo withOffset(double offsetS, OffsetEstimate how) {
            return new AssociationInfo(method, matched, dropped, droppedReference, maxDiffS, offsetS, overlap, maxGapS,
                    aMaxMps2, interpErrorBoundM, gapLimitS, droppedInGaps, gaps, how);
        }
    }

    /**
     * Errors beside ATE and RPE (see {@code org.trajeval.core.metric.ExtraMetrics}).
     *
     * @param transXM signed x error p_est - p_ref in the reference's world frame (m)
     * @param transYM signed y error (m)
     * @param transZM signed z error (m)
     * @param headingRad planar heading error |wrap(yaw_est - yaw_ref)| (rad)
     * @param speedMps speed error |v_est| - |v_ref| over the horizon (m/s)
     * @param speedHorizonS that horizon (s)
     */
    @JsonPropertyOrder({"trans_x_m", "trans_y_m", "trans_z_m", "heading_rad", "speed_mps", "speed_horizon_s"})
    public record Extra(@JsonProperty("trans_x_m") Stats transXM, @JsonProperty("trans_y_m") Stats transYM,
            @JsonProperty("trans_z_m") Stats transZM, @JsonProperty("heading_rad") Stats headingRad,
            @JsonProperty("speed_mps") Stats speedMps, @JsonProperty("speed_horizon_s") double speedHorizonS) implements java.io.Serializable {
    }

    /**
     * A clock offset estimated from the data ({@code --t-offset auto}); the offset used is
     * {@code association.t_offset_s}.
     *
     * @param correlationS the peak of the angular-speed cross-correlation (s)
     * @param uncertaintyS half-width of that peak (s)
     * @param correlation normalised correlation at the peak
     * @param method how it was found
     */
    @JsonPropertyOrder({"correlation_s", "uncertainty_s", "correlation", "method"})
    public record OffsetEstimate(@JsonProperty("correlation_s") double correlationS,
            @JsonProperty("uncertainty_s") double uncertaintyS, @JsonProperty("correlation") double correlation,
            @JsonProperty("method") String method) implements java.io.Serializable {
    }

    /**
     * A reference gap longer than the limit, with the estimate poses dropped in it.
     *
     * @param startS reference stamp before the gap (s)
     * @param endS reference stamp after the gap (s)
     * @param lengthS endS - startS (s)
     * @param dropped estimate poses dropped inside it
     */
    @JsonPropertyOrder({"start_s", "end_s", "length_s", "dropped"})
    public record Gap(@JsonProperty("start_s") double startS, @JsonProperty("end_s") double endS,
            @JsonProperty("length_s") double lengthS, @JsonProperty("dropped") int dropped) implements java.io.Serializable {
    }

    /**
     * Coverage of the reference's time span by the associated estimate (see
     * {@code org.trajeval.core.metric.Coverage}).
     *
     * @param fraction covered share, in [0, 1]
     * @param longestGapS longest stretch without an associated estimate pose (s)
     * @param longestGapStartS where it begins (s, reference clock)
     * @param uncoveredS total uncovered time (s)
     * @param referenceSpanS the reference's time span (s)
     */
    @JsonPropertyOrder({"fraction", "longest_gap_s", "longest_gap_start_s", "uncovered_s", "reference_span_s"})
    public record CoverageInfo(@JsonProperty("fraction") double fraction,
            @JsonProperty("longest_gap_s") double longestGapS,
            @JsonProperty("longest_gap_start_s") double longestGapStartS,
            @JsonProperty("uncovered_s") double uncoveredS,
            @JsonProperty("reference_span_s") double referenceSpanS) implements java.io.Serializable {
    }

    /**
     * Something a careful user should know about the numbers, with the option that avoids it.
     *
     * @param code stable machine-readable name, e.g. {@code poses_dropped_in_reference_gaps}
     * @param message one line for people
     */
    @JsonPropertyOrder({"code", "message"})
    public record Warning(@JsonProperty("code") String code, @JsonProperty("message") String message) implements java.io.Serializable {
    }

    /**
     * The fitted transform p_aligned = scale * R p_est + t, applied to whole poses.
     *
     * @param model none, se2, sim2, se3, sim3, origin, posyaw
     * @param rotation 3x3 rotation matrix, row-major rows
     * @param translationM translation t (m)
     * @param scale scale factor (1 for rigid models)
     * @param posesUsed number of associated poses the fit used
     */
    @JsonPropertyOrder({"model", "rotation", "translation_m", "scale", "poses_used"})
    public record AlignmentInfo(@JsonProperty("model") String model, @JsonProperty("rotation") double[][] rotation,
            @JsonProperty("translation_m") double[] translationM, @JsonProperty("scale") double scale,
            @JsonProperty("poses_used") int posesUsed) implements java.io.Serializable {
    }

    /**
     * @param transM statistics of the translation errors |t_est - t_ref| (m)
     * @param rotRad statistics of the rotation errors (rad): |wrap(yaw_est - yaw_ref)| in SE(2),
     *     the angle of R_ref^T R_est in SE(3)
     */
    @JsonPropertyOrder({"trans_m", "rot_rad"})
    public record Ate(@JsonProperty("trans_m") Stats transM, @JsonProperty("rot_rad") Stats rotRad) implements java.io.Serializable {
    }

    /**
     * @param transM statistics of |trans(E_ij)| (m), E_ij = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j)
     * @param rotRad statistics of the rotation angle of E_ij (rad)
     * @param pairs number of pairs (i, j)
     * @param delta the horizon asked for, in {@code unit}
     * @param unit s, frames or m
     * @param pairSelection consecutive or all_pairs
     * @param pairsFrom reference or estimate
     * @param meanHorizonS mean of t_j - t_i over the pairs actually used (s)
     * @param meanHorizonM mean reference path length between i and j over the pairs (m)
     */
    @JsonPropertyOrder({"trans_m", "rot_rad", "pairs", "delta", "unit", "pair_selection", "pairs_from",
        "mean_horizon_s", "mean_horizon_m"})
    public record Rpe(@JsonProperty("trans_m") Stats transM, @JsonProperty("rot_rad") Stats rotRad,
            @JsonProperty("pairs") long pairs, @JsonProperty("delta") double delta,
            @JsonProperty("unit") String unit, @JsonProperty("pair_selection") String pairSelection,
            @JsonProperty("pairs_from") String pairsFrom, @JsonProperty("mean_horizon_s") Double meanHorizonS,
            @JsonProperty("mean_horizon_m") Double meanHorizonM) implements java.io.Serializable {
    }

    /**
     * KITTI-style drift: averages over all segments of all lengths.
     *
     * @param transPct mean translational error per segment length (%)
     * @param rotDegPerM mean rotational error per segment length (deg/m)
     * @param segments number of segments evaluated
     * @param stepFrames frames between segment starts
     * @param perLength the same figures per segment length
     */
    @JsonPropertyOrder({"trans_pct", "rot_deg_per_m", "rot_deg_per_100m", "rot_rad_per_m", "segments", "step_frames",
        "path_length_m", "per_length"})
    public record Drift(@JsonProperty("trans_pct") Double transPct,
            @JsonProperty("rot_deg_per_m") Double rotDegPerM, @JsonProperty("segments") int segments,
            @JsonProperty("step_frames") int stepFrames,
            @JsonProperty("per_length") java.util.List<DriftAtLength> perLength,
            @JsonProperty("path_length_m") Double pathLengthM) implements java.io.Serializable {

        /** @return rotational drift in KITTI's unit, deg per 100 m (null without segments) */
        @JsonProperty("rot_deg_per_100m")
        public Double rotDegPer100m() {
            return rotDegPerM == null ? null : 100.0 * rotDegPerM;
        }

        /** @return rotational drift in SI, rad/m (null without segments) */
        @JsonProperty("rot_rad_per_m")
        public Double rotRadPerM() {
            return rotDegPerM == null ? null : Math.toRadians(rotDegPerM);
        }
    }

    /**
     * @param lengthM segment length (m)
     * @param transPct mean translational error (%)
     * @param rotDegPerM mean rotational error (deg/m)
     * @param segments number of segments of this length
     */
    @JsonPropertyOrder({"length_m", "trans_pct", "rot_deg_per_m", "segments"})
    public record DriftAtLength(@JsonProperty("length_m") double lengthM, @JsonProperty("trans_pct") Double transPct,
            @JsonProperty("rot_deg_per_m") Double rotDegPerM, @JsonProperty("segments") int segments) implements java.io.Serializable {
    }

    /**
     * Error statistics as written in reports (null fields when there were no values).
     * std is the population standard deviation.
     */
    @JsonPropertyOrder({"rmse", "mean", "median", "std", "min", "max", "sse", "n"})
    public record Stats(@JsonProperty("rmse") Double rmse, @JsonProperty("mean") Double mean,
            @JsonProperty("median") Double median, @JsonProperty("std") Double std,
            @JsonProperty("min") Double min, @JsonProperty("max") Double max,
            @JsonProperty("sse") Double sse, @JsonProperty("n") long n) implements java.io.Serializable {

        /**
         * Internal (not part of the public API, see {@link org.trajeval.api}): used by the evaluator.
         *
         * @return the report form of the statistics (nulls for n = 0)
         */
        public static Stats of(org.trajeval.core.stats.ErrorStatistics s) {
            if (s.n() == 0) {
                return new Stats(null, null, null, null, null, null, null, 0);
            }
            return new Stats(s.rmse(), s.mean(), s.median(), s.std(), s.min(), s.max(), s.sse(), s.n());
        }
    }
}
