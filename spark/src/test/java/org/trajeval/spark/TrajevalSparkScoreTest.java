package org.trajeval.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.apache.spark.sql.Dataset;
import org.apache.spark.sql.Row;
import org.apache.spark.sql.RowFactory;
import org.apache.spark.sql.SparkSession;
import org.apache.spark.sql.types.DataTypes;
import org.apache.spark.sql.types.StructType;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.cli.TrajevalCommand;
import org.trajeval.core.InputException;
import org.trajeval.core.options.Setting;
import org.trajeval.core.options.SettingKind;
import org.trajeval.core.protocol.RunMetric;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;
import picocli.CommandLine;

/**
 * TrajevalSpark.score in a real local[2] Spark: on evo's reference data (TUM fr1_xyz, EuRoC V1_02,
 * KITTI 00, and fr1_xyz read as planar) every result equals what trajeval eval prints for the same
 * pair and settings, byte for byte; bad pairs are failed rows with eval's message.
 */
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class TrajevalSparkScoreTest {
    private static SparkSession spark;

    @TempDir
    static Path tmp;

    private static final StructType PAIRS = new StructType()
            .add("ref", DataTypes.StringType).add("est", DataTypes.StringType)
            .add("robot", DataTypes.StringType)
            .add("convention", DataTypes.StringType).add("alignment", DataTypes.StringType)
            .add("planar", DataTypes.StringType);

    @BeforeAll
    static void start() {
        spark = LocalSpark.start();
    }

    @AfterAll
    static void stop() {
        spark.stop();
    }

    private static String data(String name) {
        return LocalSpark.refdata().resolve(name).toString();
    }

    @Test
    void everyPairGivesTrajevalEvalsReportByteForByteAndBadPairsAreFailedRows() throws Exception {
        Path garbage = Files.writeString(tmp.resolve("garbage.txt"), "this is not a trajectory\n\u0001\u0002\n");
        String missing = tmp.resolve("no-such-estimate.txt").toString();
        List<Row> rows = List.of(
                RowFactory.create(data("freiburg1_xyz-groundtruth.txt"), data("freiburg1_xyz-rgbdslam.txt"),
                        "tum-lesson", null, null, null),
                RowFactory.create(data("freiburg1_xyz-groundtruth.txt"), data("freiburg1_xyz-rgbdslam_drift.txt"),
                        "tum-evo-se3", "evo", "se3", null),
                RowFactory.create(data("freiburg1_xyz-groundtruth.txt"), data("freiburg1_xyz-ORB_kf_mono.txt"),
                        "tum-sim3", "evo", "sim3", null),
                RowFactory.create(data("freiburg1_xyz-groundtruth.txt"), data("freiburg1_xyz-rgbdslam.txt"),
                        "planar", null, null, "true"),
                RowFactory.create(data("V102_groundtruth.csv"), data("V102.txt"), "euroc", "evo", "se3", null),
                RowFactory.create(data("KITTI_00_gt.txt"), data("KITTI_00_ORB.txt"), "kitti", "kitti", null, null),
                RowFactory.create(data("freiburg1_xyz-groundtruth.txt"), missing, "missing", null, null, null),
                RowFactory.create(data("freiburg1_xyz-groundtruth.txt"), garbage.toString(), "garbage", null, null,
                        null),
                RowFactory.create(data("freiburg1_xyz-groundtruth.txt"), data("freiburg1_xyz-rgbdslam.txt"),
                        "bad-option", null, "banana", null),
                RowFactory.create(data("freiburg1_xyz-groundtruth.txt"), "file://" + data("freiburg1_xyz-rgbdslam.txt"),
                        "file-uri", "evo", "se3", null),
                RowFactory.create(data("freiburg1_xyz-groundtruth.txt"), "s3a://bucket/freiburg1_xyz-rgbdslam.txt",
                        "s3a", null, null, null));
        Dataset<Row> pairs = spark.createDataFrame(rows, PAIRS).repartition(3);

        List<Row> out = TrajevalSpark.score(pairs, Map.of()).collectAsList();

        assertEquals(rows.size(), out.size(), "one result row per pair");
        Map<String, Row> byRobot = new HashMap<>();
        for (Row r : out) {
            assertEquals(ResultSchema.VERSION, r.<Integer>getAs(ResultSchema.RESULT_SCHEMA_VERSION));
            byRobot.put(r.getAs("robot"), r);
        }
        assertEquals(rows.size(), byRobot.size(), "every pair exactly once");
        for (Row in : rows) {
            Row r = byRobot.get(in.getString(2));
            Eval eval = eval(in);
            if (eval.exit == 0) {
                assertEquals(ResultSchema.OK, r.getAs(ResultSchema.STATUS), in.getString(2) + ": " + r.getAs(ResultSchema.FAILURE_DETAIL));
                assertEquals(eval.out, r.<String>getAs(ResultSchema.REPORT) + "\n", in.getString(2)
                        + ": the report equals trajeval eval --json byte for byte");
                EvaluationReport rep = ReportJson.parseEvaluation(eval.out);
                for (RunMetric m : RunMetric.values()) {
                    Double v = r.getAs(m.key());
                    double expected = m.of(rep);
                    if (Double.isNaN(expected)) {
                        assertNull(v, m.key());
                    } else {
                        assertEquals(Double.doubleToLongBits(expected), Double.doubleToLongBits(v), m.key());
                    }
                }
                assertEquals(rep.association().matched(), r.<Integer>getAs(ResultSchema.MATCHED));
                assertEquals(rep.association().dropped(), r.<Integer>getAs(ResultSchema.DROPPED));
            } else {
                assertEquals(2, eval.exit, in.getString(2) + ": eval refuses the pair as bad input");
                assertEquals(ResultSchema.FAILED, r.getAs(ResultSchema.STATUS), in.getString(2));
                assertNull(r.getAs(ResultSchema.REPORT));
                assertNull(r.getAs(RunMetric.ATE_TRANS_RMSE_M.key()));
            }
        }
        assertEquals("unreadable", byRobot.get("missing").getAs(ResultSchema.FAILURE_REASON));
        assertEquals(firstLine(eval(rows.get(6)).err), "trajeval: " + byRobot.get("missing").getAs(ResultSchema.FAILURE_DETAIL),
                "a missing file: eval's message");
        assertEquals(firstLine(eval(rows.get(7)).err), "trajeval: " + byRobot.get("garbage").getAs(ResultSchema.FAILURE_DETAIL),
                "a garbage file: eval's message");
        assertEquals("unreadable", byRobot.get("s3a").getAs(ResultSchema.FAILURE_REASON),
                "a file system whose Hadoop module is not on the class path: "
                        + byRobot.get("s3a").getAs(ResultSchema.FAILURE_DETAIL));
        String s3a = byRobot.get("s3a").getAs(ResultSchema.FAILURE_DETAIL);
        assertTrue(s3a.startsWith("s3a://bucket/freiburg1_xyz-rgbdslam.txt: ") && s3a.contains("hadoop-aws"), s3a);
        Row bad = byRobot.get("bad-option");
        assertEquals("invalid_configuration", bad.getAs(ResultSchema.FAILURE_REASON));
        String msg = bad.getAs(ResultSchema.FAILURE_DETAIL);
        assertTrue(msg.contains("column alignment") && msg.contains("banana"), msg);
        // passthrough: the input's columns come back unchanged, in front
        Row kitti = byRobot.get("kitti");
        assertEquals(data("KITTI_00_ORB.txt"), kitti.getAs("est"));
        assertEquals("kitti", kitti.getAs("convention"));
        assertEquals(Arrays.asList(PAIRS.fieldNames()), Arrays.asList(kitti.schema().fieldNames()).subList(0, 6));
    }

    @Test
    void aTableWithoutEstColumnOrWithBadJobSettingsIsRefusedBeforeAnythingRuns() {
        Dataset<Row> noEst = spark.createDataFrame(List.of(RowFactory.create("a")),
                new StructType().add("ref", DataTypes.StringType));
        InputException e = assertThrows(InputException.class, () -> TrajevalSpark.score(noEst, Map.of()));
        assertEquals("est", e.column());
        Dataset<Row> ok = spark.createDataFrame(List.of(RowFactory.create("a", "b")),
                new StructType().add("ref", DataTypes.StringType).add("est", DataTypes.StringType));
        InputException s = assertThrows(InputException.class,
                () -> TrajevalSpark.score(ok, Map.of("alignment", "banana")));
        assertEquals("alignment", s.column());
    }

    @Test
    @Order(Integer.MAX_VALUE) // the job stops the session when done: last
    void theScoreJobWritesOneRowPerPairWithEvalsReportAndRefusesBadUsageWithExit2() throws Exception {
        Path csv = tmp.resolve("job-pairs.csv");
        String ref = data("freiburg1_xyz-groundtruth.txt");
        String est = data("freiburg1_xyz-rgbdslam_drift.txt");
        Files.writeString(csv, "ref,est,robot\n" + ref + "," + est + ",r1\n" + ref + "," + tmp.resolve("gone.txt")
                + ",\"r2, with a comma\"\n");
        Path outDir = tmp.resolve("job-out");
        StringWriter err = new StringWriter();
        CommandLine bad = SparkJob.commandLine();
        bad.setErr(new PrintWriter(err));
        assertEquals(SparkJob.BAD_INPUT, bad.execute("score", "--pairs", csv.toString(), "--out", outDir.toString(),
                "--no-such-option"));
        assertTrue(err.toString().startsWith("trajeval-spark: "), err.toString());

        CommandLine job = SparkJob.commandLine();
        StringWriter out = new StringWriter();
        job.setOut(new PrintWriter(out));
        int exit = job.execute("score", "--pairs", csv.toString(), "--out", outDir.toString(), "--format", "json",
                "--master", "local[2]", "--convention", "evo", "--align", "se3");
        assertEquals(SparkJob.OK, exit);
        assertTrue(out.toString().startsWith("scored 2 pairs (1 ok, 1 failed)"), out.toString());
        com.fasterxml.jackson.databind.ObjectMapper m = new com.fasterxml.jackson.databind.ObjectMapper();
        Map<String, com.fasterxml.jackson.databind.JsonNode> rows = new HashMap<>();
        try (var files = Files.list(outDir)) {
            for (Path f : files.filter(p -> p.toString().endsWith(".json")).toList()) {
                for (String line : Files.readAllLines(f)) {
                    com.fasterxml.jackson.databind.JsonNode n = m.readTree(line);
                    rows.put(n.get("robot").asText(), n);
                }
            }
        }
        assertEquals(2, rows.size());
        Eval eval = eval(RowFactory.create(ref, est, "r1", "evo", "se3", null));
        assertEquals(eval.out, rows.get("r1").get(ResultSchema.REPORT).asText() + "\n");
        assertEquals(ResultSchema.FAILED, rows.get("r2, with a comma").get(ResultSchema.STATUS).asText());

        StringWriter again = new StringWriter();
        CommandLine exists = SparkJob.commandLine();
        exists.setErr(new PrintWriter(again));
        assertEquals(SparkJob.BAD_INPUT, exists.execute("score", "--pairs", csv.toString(), "--out",
                outDir.toString(), "--master", "local[2]"));
        assertTrue(again.toString().contains("the output folder exists"), again.toString());
    }

    private record Eval(int exit, String out, String err) {
    }

    /** trajeval eval REF EST --json with the row's settings as flags, in this JVM. */
    static Eval eval(Row in) {
        // a file: URI is the local file (Hadoop's local file system); eval takes the path
        String est = in.getString(1).startsWith("file://") ? in.getString(1).substring("file://".length())
                : in.getString(1);
        List<String> args = new ArrayList<>(List.of("eval", in.getString(0), est, "--json"));
        for (int i = 3; i < in.size(); i++) {
            if (!in.isNullAt(i)) {
                Setting s = Setting.fromKey(PAIRS.fieldNames()[i]);
                args.add(s.flag());
                if (s.kind() != SettingKind.SWITCH) {
                    args.add(in.getString(i));
                }
            }
        }
        CommandLine cl = TrajevalCommand.newCommandLine();
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(err));
        int exit = cl.execute(args.toArray(String[]::new));
        return new Eval(exit, out.toString(), err.toString());
    }

    private static String firstLine(String s) {
        return s.lines().findFirst().orElse("");
    }
}
