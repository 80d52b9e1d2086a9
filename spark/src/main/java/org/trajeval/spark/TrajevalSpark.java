package org.trajeval.spark;

import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.apache.spark.sql.Dataset;
import org.apache.spark.sql.Encoders;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.types.StructType;
import org.trajeval.core.InputException;
import org.trajeval.core.options.SettingText;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsTree;

/**
 * Scores a table of trajectory pairs on Spark, with the numbers of {@code trajeval eval}.
 *
 * <pre>{@code
 * Dataset<Row> pairs = spark.read().option("header", true).csv("pairs.csv");   // ref, est, robot, ...
 * Dataset<Row> results = TrajevalSpark.score(pairs, Map.of("convention", "evo", "alignment", "se3"));
 * results.write().parquet("results/");
 * }</pre>
 *
 * <p>Input: string columns {@code ref} and {@code est} (a path, or any Hadoop FileSystem URI:
 * {@code file:}, {@code hdfs:}, {@code s3a:}, ...; see {@link PairFiles}), optional
 * per-row settings columns named as the settings' keys (a non-null cell overrides the job's
 * setting for that row), any other columns. Output: one row per input row, the input's columns
 * unchanged followed by {@link ResultSchema#RESULT}. A pair that cannot be scored (missing file,
 * bad content, unknown setting value, no overlap, ...) is a row with status {@code failed}, its
 * error kind and the message; the job does not fail for it. The transformation is lazy and
 * deterministic, so a task that Spark reruns (a lost executor) gives the same rows.
 *
 * <p>{@link #suite} runs a benchmark suite with its runs scored on the cluster and the statistics on
 * the driver: the report of {@code trajeval suite}.
 */
public final class TrajevalSpark {
    /** How refusals of the job's settings name their source. */
    public static final String SETTINGS_SOURCE = "settings";

    private TrajevalSpark() {
    }

    /**
     * @param pairs the pairs table
     * @param settings the job's settings, keys and values as in {@code run.yaml} and
     *     {@code TrajectoryEvaluator.of} (for example {@code convention: evo}, {@code rpe_delta: 10})
     * @return the results, lazily (nothing runs until an action)
     * @throws InputException now, on bad job settings or a table without string columns ref and est
     */
    public static Dataset<Row> score(Dataset<Row> pairs, Map<String, ?> settings) {
        Objects.requireNonNull(settings, "settings");
        return score(pairs, SettingsTree.flatten(settings, "", SETTINGS_SOURCE));
    }

    /** As {@link #score(Dataset, Map)}, with the settings as text (named as the user wrote them: flags or keys). */
    static Dataset<Row> score(Dataset<Row> pairs, List<SettingText> settings) {
        Objects.requireNonNull(pairs, "pairs");
        SettingValues.of(settings, SETTINGS_SOURCE); // refuses bad job settings on the driver
        StructType in = pairs.schema();
        PairColumns columns = PairColumns.of(in, "pairs table");
        PairFiles files = new PairFiles(pairs.sparkSession().sparkContext().hadoopConfiguration());
        return pairs.mapPartitions(new PairScorer(columns, settings, files), Encoders.row(ResultSchema.appendedTo(in)));
    }

    /**
     * Runs a benchmark suite: planned on the driver, every (method, sequence, seed) run scored by a
     * task of the cluster, the statistics on the driver. The report equals {@code trajeval suite}'s
     * for the same manifest and settings.
     *
     * <pre>{@code
     * SuiteRunner.Result r = TrajevalSpark.suite(spark, Path.of("bench/suite.yaml"), SuiteRunner.Settings.defaults(1));
     * SuiteReportFiles.write(r.report(), Path.of("report"));
     * }</pre>
     *
     * @param spark the session
     * @param manifest the suite manifest; its folder (every file it names) must be readable at the same
     *     path on every executor: local mode, or a shared file system mounted on every worker
     * @param settings the statistics' settings (seed, level, resamples, power, targets, leakage allowed)
     * @return the report (what report.json holds) and the plots of the HTML page
     * @throws InputException on a bad manifest, reference or setting, before any run is scored
     * @throws org.trajeval.core.protocol.SplitLeakageException on split leakage unless allowed
     */
    public static org.trajeval.core.protocol.SuiteRunner.Result suite(org.apache.spark.sql.SparkSession spark,
            java.nio.file.Path manifest, org.trajeval.core.protocol.SuiteRunner.Settings settings) {
        Objects.requireNonNull(spark, "spark");
        return SuiteJob.run(spark, manifest, settings.checked(), null);
    }
}
