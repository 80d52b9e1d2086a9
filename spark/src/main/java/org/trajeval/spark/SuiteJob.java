package org.trajeval.spark;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.apache.spark.sql.Dataset;
import org.apache.spark.sql.Encoders;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.RowFactory;
import org.apache.spark.sql.SparkSession;
import org.apache.spark.sql.types.DataTypes;
import org.apache.spark.sql.types.StructType;
import org.trajeval.core.InputException;
import org.trajeval.core.protocol.ManifestParser;
import org.trajeval.core.protocol.RunEngine;
import org.trajeval.core.protocol.RunResult;
import org.trajeval.core.protocol.RunScorer;
import org.trajeval.core.protocol.RunTask;
import org.trajeval.core.protocol.SuiteAssembly;
import org.trajeval.core.protocol.SuiteManifest;
import org.trajeval.core.protocol.SuitePlan;
import org.trajeval.core.protocol.SuiteRunner;

/**
 * A suite on Spark, in core's three steps: the {@link SuitePlan} on the driver (hygiene checks, the
 * references, the run tasks), each run task a row of a Dataset scored on the cluster by core's
 * {@link RunScorer} ({@link SuiteRunScorer}), the results collected to the driver and the analysis
 * ({@link SuiteAssembly}) there. The report equals {@code trajeval suite}'s for the same manifest
 * and settings: the tasks are the same, each is scored by the same code, and the analysis sees the
 * results in the plan's order whichever task ran where and how often.
 */
final class SuiteJob {
    /** The run tasks, one row per run: {@link RunTask}'s components. */
    static final StructType TASKS = new StructType()
            .add("task", DataTypes.IntegerType, false).add("method", DataTypes.StringType, false)
            .add("sequence", DataTypes.StringType, false).add("seed", DataTypes.LongType, false)
            .add("estimate", DataTypes.StringType, false);
    /** The scored runs: the task's index and its {@link RunResult}, Java-serialised (every number bit for bit). */
    static final StructType RESULTS = new StructType()
            .add("task", DataTypes.IntegerType, false).add("result", DataTypes.BinaryType, false);

    private SuiteJob() {
    }

    /**
     * @param spark the session
     * @param manifest the manifest, in a folder every executor reads at the same path (local mode, or a
     *     shared file system mounted on every worker)
     * @param settings the statistics' settings
     * @param partitions tasks to spread the runs over, or {@code null} for the session's default parallelism
     * @return the report and the plots
     * @throws InputException on a bad manifest, reference or setting (on the driver, before any run)
     * @throws org.trajeval.core.protocol.SplitLeakageException on leakage unless allowed
     */
    static SuiteRunner.Result run(SparkSession spark, Path manifest, SuiteRunner.Settings settings,
            Integer partitions) {
        Path file = manifest.toAbsolutePath().normalize();
        SuiteManifest m = new ManifestParser().read(file);
        SuitePlan plan = SuitePlan.of(m, file, settings, new RunScorer(RunEngine.standard(), m, file));
        List<Row> rows = new ArrayList<>();
        for (RunTask t : plan.tasks()) {
            rows.add(RowFactory.create(t.index(), t.method(), t.sequence(), t.seed(), t.estimate()));
        }
        int n = partitions != null ? partitions
                : Math.max(1, Math.min(rows.size(), spark.sparkContext().defaultParallelism()));
        Dataset<Row> tasks = spark.createDataFrame(rows, TASKS).repartition(n);
        List<Row> scored;
        try {
            scored = tasks.mapPartitions(new SuiteRunScorer(file.toString(), plan.manifestSha256()),
                    Encoders.row(RESULTS)).collectAsList();
        } catch (RuntimeException e) {
            throw inputProblemIn(e);
        }
        RunResult[] results = new RunResult[plan.tasks().size()];
        for (Row r : scored) {
            int i = r.getInt(0);
            if (results[i] != null) {
                throw new IllegalStateException("task " + i + " returned twice");
            }
            results[i] = deserialise(r.getAs(1));
        }
        for (int i = 0; i < results.length; i++) {
            if (results[i] == null) {
                throw new IllegalStateException("task " + i + " (" + plan.tasks().get(i) + ") returned no result");
            }
        }
        return SuiteAssembly.assemble(plan, List.of(results), settings);
    }

    /**
     * A run never fails its task (a bad estimate is a failed run); what does is the suite's own input
     * as an executor sees it (the manifest changed, a reference it cannot read): that refusal, if Spark
     * kept it, else the exception as it is.
     */
    private static RuntimeException inputProblemIn(RuntimeException e) {
        for (Throwable c = e; c != null; c = c.getCause()) {
            if (c instanceof InputException ie) {
                return ie;
            }
        }
        return e;
    }

    private static RunResult deserialise(byte[] bytes) {
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes))) {
            return (RunResult) in.readObject();
        } catch (IOException | ClassNotFoundException e) {
            throw new IllegalStateException("a run's result could not be read back", e);
        }
    }
}
