package org.trajeval.spark;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import org.apache.spark.sql.SparkSession;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.protocol.SuiteRunner;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.figures.SuiteReportFolder;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code trajeval-spark suite MANIFEST --out DIR}: a benchmark suite with its runs scored on Spark
 * and the statistics on the driver; the report folder of {@code trajeval suite} (same options of
 * the statistics, same files, same report.json).
 */
@Command(name = "suite", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Runs a benchmark suite with every (method, sequence, seed) run scored by a Spark task and "
            + "the statistics on the driver: the report of trajeval suite for the same manifest and options.",
            "Writes report.json, runs.csv, methods.csv, comparisons.csv, report.html and, with three or more "
                + "methods, one average-rank diagram per metric (ranks_METRIC.svg) into --out (on the driver).",
            "The manifest's folder must be readable at the same path on every executor (local mode, or a shared "
                + "file system mounted on every worker)."})
final class SuiteCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "MANIFEST", description = "Suite manifest (YAML).")
    Path manifest;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Report folder (created).")
    Path out;

    @Option(names = "--master", paramLabel = "URL",
            description = "Spark master (local[N], spark://HOST:PORT, yarn, ...); default: spark-submit's, else "
                    + SparkSessions.DEFAULT_MASTER + ".")
    String master;

    @Option(names = "--partitions", paramLabel = "N",
            description = "Tasks to spread the runs over (default: Spark's default parallelism).")
    Integer partitions;

    @Option(names = "--seed", paramLabel = "N", defaultValue = "1",
            description = "Seed of the bootstrap resampling (default: ${DEFAULT-VALUE}); same seed, same bytes.")
    long seed;

    @Option(names = "--confidence", paramLabel = "LEVEL", defaultValue = "0.95",
            description = "Confidence level of every interval (default: ${DEFAULT-VALUE}).")
    double confidence;

    @Option(names = "--resamples", paramLabel = "B", defaultValue = "4000",
            description = "Bootstrap resamples, 100 to 1000000 (default: ${DEFAULT-VALUE}).")
    int resamples;

    @Option(names = "--power", paramLabel = "P", defaultValue = "0.8",
            description = "Power of the planning figures (default: ${DEFAULT-VALUE}).")
    double power;

    @Option(names = "--detect", paramLabel = "METRIC=DIFF",
            description = "Report how many sequences a mean difference DIFF on METRIC needs; repeatable.")
    Map<String, Double> detect = new LinkedHashMap<>();

    @Option(names = "--allow-leakage", description = "Run despite split leakage; the report flags it.")
    boolean allowLeakage;

    @Override
    public Integer call() {
        SuiteRunner.Settings settings = new SuiteRunner.Settings(seed, allowLeakage, confidence, resamples, power,
                detect).checked();
        if (partitions != null && partitions < 1) {
            throw new InputException(null, 0, "--partitions", InputProblem.OUT_OF_RANGE, "--partitions must be at "
                    + "least 1", partitions.toString());
        }
        SuiteReportFolder.refuseToReplaceInputs(manifest, out, "--out");
        long start = System.nanoTime();
        SparkSession spark = SparkSessions.open(master, "trajeval-spark suite");
        try {
            SuiteRunner.Result result = SuiteJob.run(spark, manifest, settings, partitions);
            SuiteReportFolder.write(result, out);
            SuiteReport r = result.report();
            PrintWriter o = spec.commandLine().getOut();
            for (String w : r.hygiene().warnings()) {
                o.println("WARNING: " + w);
            }
            long failed = r.runs().stream().filter(x -> !x.ok()).count();
            o.printf(Locale.ROOT, "scored %d runs (%d ok, %d failed) in %.1f s on %s; wrote %s (%s)%n",
                    r.runs().size(), r.runs().size() - failed, failed, (System.nanoTime() - start) / 1e9,
                    spark.sparkContext().master(), out, String.join(", ", SuiteReportFolder.FILES));
            o.flush();
            return SparkJob.OK;
        } finally {
            spark.stop();
        }
    }
}
