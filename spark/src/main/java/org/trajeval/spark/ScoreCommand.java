package org.trajeval.spark;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.apache.hadoop.fs.FileSystem;
import org.apache.spark.sql.Dataset;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.SparkSession;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.options.SettingText;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Unmatched;
import picocli.CommandLine.Model.CommandSpec;

/** {@code trajeval-spark score}: a pairs table in, a results table out (one row per pair). */
@Command(name = "score", mixinStandardHelpOptions = true,
        description = {"Scores every pair of a table (columns ref, est, optional settings columns named as the "
                + "settings' keys, any others passed through) and writes one result row per pair.",
            "Every option of trajeval eval (--convention, --align, --rpe-delta, --planar, ...) is accepted and "
                + "applies to every pair; a non-empty settings column overrides it for its row."})
final class ScoreCommand implements Callable<Integer> {
    /** Output formats. */
    enum Format { PARQUET, CSV, JSON }

    @Spec
    CommandSpec spec;

    @Option(names = "--pairs", required = true, paramLabel = "PAIRS",
            description = "The pairs table: a .csv file with a header line, or Parquet (a .parquet file or folder).")
    String pairs;

    @Option(names = "--out", required = true, paramLabel = "DIR",
            description = "Output folder (a path or Hadoop URI); must not exist.")
    String out;

    @Option(names = "--format", paramLabel = "parquet|csv|json", defaultValue = "parquet",
            description = "Output format (default: ${DEFAULT-VALUE}).")
    String format;

    @Option(names = "--master", paramLabel = "URL",
            description = "Spark master (local[N], spark://HOST:PORT, yarn, ...); default: spark-submit's, else "
                    + SparkSessions.DEFAULT_MASTER + ".")
    String master;

    @Option(names = "--partitions", paramLabel = "N",
            description = "Tasks to spread the pairs over (default: Spark's default parallelism, at least the "
                    + "table's own partitions).")
    Integer partitions;

    @Unmatched
    List<String> evalOptions = new ArrayList<>();

    @Override
    public Integer call() throws Exception {
        Format fmt = format();
        List<SettingText> settings = EvalFlags.parse(evalOptions);
        if (partitions != null && partitions < 1) {
            throw new InputException(null, 0, "--partitions", InputProblem.OUT_OF_RANGE, "--partitions must be at "
                    + "least 1", partitions.toString());
        }
        long start = System.nanoTime();
        SparkSession spark = SparkSessions.open(master, "trajeval-spark score");
        try {
            org.apache.hadoop.fs.Path outPath = new org.apache.hadoop.fs.Path(out);
            FileSystem fs = outPath.getFileSystem(spark.sparkContext().hadoopConfiguration());
            if (fs.exists(outPath)) {
                throw new InputException(out, 0, "--out", InputProblem.INVALID_OPTION, "the output folder exists; "
                        + "give a new one (nothing is overwritten)", null);
            }
            Dataset<Row> table = read(spark);
            int n = partitions != null ? partitions : Math.max(spark.sparkContext().defaultParallelism(),
                    table.rdd().getNumPartitions());
            Dataset<Row> results = TrajevalSpark.score(table.repartition(n), settings);
            // CSV as RFC 4180 ("" inside quoted fields; the report column spans lines)
            results.write().format(fmt.name().toLowerCase(Locale.ROOT)).option("header", "true")
                    .option("escape", "\"").save(out);
            List<Row> counts = spark.read().format(fmt.name().toLowerCase(Locale.ROOT)).option("header", "true")
                    .option("escape", "\"").option("multiLine", "true").load(out).groupBy(ResultSchema.STATUS)
                    .count().collectAsList();
            long ok = 0;
            long failed = 0;
            for (Row r : counts) {
                if (ResultSchema.OK.equals(r.getString(0))) {
                    ok = r.getLong(1);
                } else {
                    failed += r.getLong(1);
                }
            }
            PrintWriter o = spec.commandLine().getOut();
            o.printf(Locale.ROOT, "scored %d pairs (%d ok, %d failed) in %.1f s on %s; wrote %s (%s)%n", ok + failed,
                    ok, failed, (System.nanoTime() - start) / 1e9, spark.sparkContext().master(), out,
                    fmt.name().toLowerCase(Locale.ROOT));
            o.flush();
            return SparkJob.OK;
        } finally {
            spark.stop();
        }
    }

    private Format format() {
        try {
            return Format.valueOf(format.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new InputException(null, 0, "--format", InputProblem.INVALID_OPTION, "--format must be parquet, "
                    + "csv or json", format);
        }
    }

    /** The pairs table: CSV (every column a string) by its extension, else Parquet. */
    private Dataset<Row> read(SparkSession spark) {
        String lower = pairs.toLowerCase(Locale.ROOT);
        if (lower.endsWith(".csv")) {
            return spark.read().option("header", "true").option("inferSchema", "false").option("escape", "\"").csv(pairs);
        }
        if (lower.endsWith(".parquet") || Files.isDirectory(Path.of(pairs)) || pairs.contains("://")) {
            return spark.read().parquet(pairs);
        }
        throw new InputException(pairs, 0, "--pairs", InputProblem.UNKNOWN_FORMAT, "the pairs table must be a .csv "
                + "file (with a header line) or Parquet (.parquet, or a folder of Parquet files)", null);
    }
}
