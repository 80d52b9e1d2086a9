package org.trajeval.spark;

import java.util.ArrayList;
import java.util.List;
import org.apache.spark.sql.types.DataTypes;
import org.apache.spark.sql.types.StructField;
import org.apache.spark.sql.types.StructType;
import org.trajeval.core.protocol.RunMetric;

/**
 * The result columns {@link TrajevalSpark#score} appends to every input row (schema version
 * {@value #VERSION}; a column is only ever added within a version). The input's own columns come
 * first, unchanged; then:
 *
 * <ul>
 *   <li>{@code result_schema_version} (int): {@value #VERSION};
 *   <li>{@code status} (string): {@code ok} or {@code failed};
 *   <li>{@code failure_reason} (string): for a failed pair, the problem of the refusal in lower
 *       case ({@code unreadable}, {@code not_a_number}, {@code invalid_configuration},
 *       {@code no_overlap}, ...) or {@code internal_error} (a bug: report it); null when ok;
 *   <li>{@code failure_detail} (string): the one-line message {@code trajeval eval} prints for that
 *       pair; (status and the two failure columns as in a suite's {@code runs.csv} and
 *       {@code eval --batch}'s {@code summary.csv});
 *   <li>one double per statistic, named as the suite's {@code runs.csv} ({@link RunMetric} keys:
 *       {@code ate_trans_rmse_m}, {@code ate_trans_mean_m}, {@code ate_rot_rmse_rad},
 *       {@code rpe_trans_rmse_m}, {@code rpe_rot_rmse_rad}, {@code drift_trans_pct}), null when the
 *       report has no such value;
 *   <li>{@code ate_trans_max_m} (m), {@code coverage} (fraction of the reference's span covered,
 *       0..1), {@code matched}, {@code dropped}, {@code dropped_reference} (pose counts),
 *       {@code ref_poses}, {@code est_poses}, {@code alignment_model} (the model used);
 *   <li>{@code warnings} (string): the report's warning codes joined by ';', empty when none;
 *   <li>{@code report} (string): the whole evaluation report, byte for byte what
 *       {@code trajeval eval --json} prints for the pair (schema {@code trajeval.evaluation}).
 * </ul>
 */
public final class ResultSchema {
    /** Version of the result columns. */
    public static final int VERSION = 1;

    public static final String RESULT_SCHEMA_VERSION = "result_schema_version";
    public static final String STATUS = "status";
    public static final String FAILURE_REASON = "failure_reason";
    public static final String FAILURE_DETAIL = "failure_detail";
    public static final String ATE_TRANS_MAX_M = "ate_trans_max_m";
    public static final String COVERAGE = "coverage";
    public static final String MATCHED = "matched";
    public static final String DROPPED = "dropped";
    public static final String DROPPED_REFERENCE = "dropped_reference";
    public static final String REF_POSES = "ref_poses";
    public static final String EST_POSES = "est_poses";
    public static final String ALIGNMENT = "alignment_model";
    public static final String WARNINGS = "warnings";
    public static final String REPORT = "report";

    /** {@code status} of a scored pair. */
    public static final String OK = org.trajeval.core.batch.BatchResult.OK;
    /** {@code status} of a pair that could not be scored. */
    public static final String FAILED = org.trajeval.core.batch.BatchResult.FAILED;

    /** The result columns, in order. */
    public static final StructType RESULT = build();

    private ResultSchema() {
    }

    /** @return the input's columns followed by the result columns */
    public static StructType appendedTo(StructType input) {
        StructType out = input;
        for (StructField f : RESULT.fields()) {
            out = out.add(f);
        }
        return out;
    }

    private static StructType build() {
        List<StructField> f = new ArrayList<>();
        f.add(DataTypes.createStructField(RESULT_SCHEMA_VERSION, DataTypes.IntegerType, false));
        f.add(DataTypes.createStructField(STATUS, DataTypes.StringType, false));
        f.add(DataTypes.createStructField(FAILURE_REASON, DataTypes.StringType, true));
        f.add(DataTypes.createStructField(FAILURE_DETAIL, DataTypes.StringType, true));
        for (RunMetric m : RunMetric.values()) {
            f.add(DataTypes.createStructField(m.key(), DataTypes.DoubleType, true));
        }
        f.add(DataTypes.createStructField(ATE_TRANS_MAX_M, DataTypes.DoubleType, true));
        f.add(DataTypes.createStructField(COVERAGE, DataTypes.DoubleType, true));
        for (String count : List.of(MATCHED, DROPPED, DROPPED_REFERENCE, REF_POSES, EST_POSES)) {
            f.add(DataTypes.createStructField(count, DataTypes.IntegerType, true));
        }
        f.add(DataTypes.createStructField(ALIGNMENT, DataTypes.StringType, true));
        f.add(DataTypes.createStructField(WARNINGS, DataTypes.StringType, true));
        f.add(DataTypes.createStructField(REPORT, DataTypes.StringType, true));
        return DataTypes.createStructType(f);
    }
}
