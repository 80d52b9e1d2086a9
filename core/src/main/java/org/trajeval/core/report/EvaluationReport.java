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
 */
@JsonPropertyOrder({"schema", "schema_version", "version", "convention", "inputs", "association", "alignment",
    "ate", "rpe", "drift"})
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
        @JsonProperty("drift") Drift drift) {

    /** Name of the report schema. */
    public static final String SCHEMA = "trajeval.evaluation";
    /** Version of the report schema; bumped on any incompatible change. */
    public static final int SCHEMA_VERSION = 1;

    /** @return this report with other inputs (trajectories given as arrays through the Java API) */
    public EvaluationReport withInputs(Inputs other) {
        return new EvaluationReport(schema, schemaVersion, version, convention, other, association, alignment, ate,
                rpe, drift);
    }

    /**
     * @param reference the reference (ground truth) input
     * @param estimate the estimate input
     */
    @JsonPropertyOrder({"reference", "estimate"})
    public record Inputs(@JsonProperty("reference") InputInfo reference,
            @JsonProperty("estimate") InputInfo estimate) {
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
            @JsonProperty("sha256") String sha256) {
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
     */
    @JsonPropertyOrder({"method", "matched", "dropped", "dropped_reference", "max_diff_s", "t_offset_s", "overlap",
        "max_gap_s", "a_max_mps2", "interp_error_bound_m"})
    public record AssociationInfo(@JsonProperty("method") String method, @JsonProperty("matched") int matched,
            @JsonProperty("dropped") int dropped, @JsonProperty("dropped_reference") int droppedReference,
            @JsonProperty("max_diff_s") double maxDiffS, @JsonProperty("t_offset_s") double tOffsetS,
            @JsonProperty("overlap") String overlap, @JsonProperty("max_gap_s") double maxGapS,
            @JsonProperty("a_max_mps2") Double aMaxMps2,
            @JsonProperty("interp_error_bound_m") Double interpErrorBoundM) {
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
            @JsonProperty("poses_used") int posesUsed) {
    }

    /**
     * @param transM statistics of the translation errors |t_est - t_ref| (m)
     * @param rotRad statistics of the rotation errors (rad): |wrap(yaw_est - yaw_ref)| in SE(2),
     *     the angle of R_ref^T R_est in SE(3)
     */
    @JsonPropertyOrder({"trans_m", "rot_rad"})
    public record Ate(@JsonProperty("trans_m") Stats transM, @JsonProperty("rot_rad") Stats rotRad) {
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
            @JsonProperty("mean_horizon_m") Double meanHorizonM) {
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
    @JsonPropertyOrder({"trans_pct", "rot_deg_per_m", "segments", "step_frames", "per_length"})
    public record Drift(@JsonProperty("trans_pct") Double transPct,
            @JsonProperty("rot_deg_per_m") Double rotDegPerM, @JsonProperty("segments") int segments,
            @JsonProperty("step_frames") int stepFrames,
            @JsonProperty("per_length") java.util.List<DriftAtLength> perLength) {
    }

    /**
     * @param lengthM segment length (m)
     * @param transPct mean translational error (%)
     * @param rotDegPerM mean rotational error (deg/m)
     * @param segments number of segments of this length
     */
    @JsonPropertyOrder({"length_m", "trans_pct", "rot_deg_per_m", "segments"})
    public record DriftAtLength(@JsonProperty("length_m") double lengthM, @JsonProperty("trans_pct") Double transPct,
            @JsonProperty("rot_deg_per_m") Double rotDegPerM, @JsonProperty("segments") int segments) {
    }

    /**
     * Error statistics as written in reports (null fields when there were no values).
     * std is the population standard deviation.
     */
    @JsonPropertyOrder({"rmse", "mean", "median", "std", "min", "max", "sse", "n"})
    public record Stats(@JsonProperty("rmse") Double rmse, @JsonProperty("mean") Double mean,
            @JsonProperty("median") Double median, @JsonProperty("std") Double std,
            @JsonProperty("min") Double min, @JsonProperty("max") Double max,
            @JsonProperty("sse") Double sse, @JsonProperty("n") long n) {

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
