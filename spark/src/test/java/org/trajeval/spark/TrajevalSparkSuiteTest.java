package org.trajeval.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.apache.spark.sql.SparkSession;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.MethodOrderer;
import org.junit.jupiter.api.Order;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestMethodOrder;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.cli.TrajevalCommand;
import org.trajeval.core.protocol.DemoBenchmark;
import org.trajeval.core.protocol.RefdataSuite;
import org.trajeval.core.protocol.SuiteRunner;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.figures.SuiteReportFolder;
import picocli.CommandLine;

/**
 * {@code trajeval-spark suite} in a real local[2] Spark writes the report folder of
 * {@code trajeval suite} (run in this JVM) for the same manifest and options, on the seeded demo
 * suite (120 runs, one judged failure, leakage allowed) and on a suite of evo's reference data
 * (with a run whose estimate is missing). The files are compared whole, byte for byte: no field is
 * excluded, because report.json holds no timing or host field (the budget section's wall and CPU
 * times come from the manifest's resources table, not from the run; the tool prints its own time
 * on stdout only).
 */
@TestMethodOrder(MethodOrderer.OrderAnnotation.class)
class TrajevalSparkSuiteTest {
    private static SparkSession spark;

    @TempDir
    static Path tmp;
    private static Path demo;
    private static Path refdata;

    @BeforeAll
    static void start() {
        spark = LocalSpark.start();
        demo = DemoBenchmark.write(tmp.resolve("demo"), 7).toAbsolutePath();
        refdata = RefdataSuite.write(tmp.resolve("refdata"), LocalSpark.refdata()).toAbsolutePath();
    }

    @AfterAll
    static void stop() {
        spark.stop();
    }

    @Test
    @Order(1)
    void demoSuiteOnSparkWritesTheFilesOfTrajevalSuite() throws IOException {
        Path expected = trajevalSuite(demo, "demo-cli", "--allow-leakage");
        Path actual = tmp.resolve("demo-spark");
        // three tasks for 120 runs: runs of one sequence land in different tasks
        SuiteRunner.Result r = SuiteJob.run(spark, demo, SuiteRunner.Settings.defaults(1).withAllowLeakage(true), 3);
        SuiteReportFolder.write(r, actual);
        assertSameFolders(expected, actual);
        assertEquals(120, r.report().runs().size());
    }

    @Test
    @Order(2)
    void refdataSuiteOnSparkWritesTheFilesOfTrajevalSuiteWithTheMissingEstimateFailedAlike() throws IOException {
        Path expected = trajevalSuite(refdata, "refdata-cli");
        Path actual = tmp.resolve("refdata-spark");
        SuiteRunner.Result r = TrajevalSpark.suite(spark, refdata, SuiteRunner.Settings.defaults(1));
        SuiteReportFolder.write(r, actual);
        assertSameFolders(expected, actual);
        List<SuiteReport.RunEntry> failed = r.report().runs().stream().filter(x -> !x.ok()).toList();
        assertEquals(1, failed.size());
        assertEquals("rgbdslam", failed.get(0).method());
        assertEquals("fr2_desk", failed.get(0).sequence());
        assertEquals("missing_estimate", failed.get(0).failure().reason());
    }

    @Test
    @Order(Integer.MAX_VALUE) // the job stops the session when done: last
    void theSuiteJobWritesTheReportFolderAndExitsAsTrajevalSuite() throws IOException {
        StringWriter usage = new StringWriter();
        CommandLine bad = SparkJob.commandLine();
        bad.setErr(new PrintWriter(usage));
        assertEquals(SparkJob.BAD_INPUT, bad.execute("suite", refdata.toString(), "--out",
                tmp.resolve("never").toString(), "--partitions", "0"));
        assertTrue(usage.toString().startsWith("trajeval-spark: "), usage.toString());

        StringWriter leak = new StringWriter();
        CommandLine leaky = SparkJob.commandLine();
        leaky.setErr(new PrintWriter(leak));
        assertEquals(SparkJob.LEAKAGE, leaky.execute("suite", demo.toString(), "--out",
                tmp.resolve("leaky").toString(), "--master", "local[2]"));
        assertTrue(leak.toString().startsWith("trajeval-spark: "), leak.toString());
        assertEquals(1, leak.toString().lines().count(), leak.toString());

        Path out = tmp.resolve("refdata-job");
        StringWriter o = new StringWriter();
        CommandLine job = SparkJob.commandLine();
        job.setOut(new PrintWriter(o));
        assertEquals(SparkJob.OK, job.execute("suite", refdata.toString(), "--out", out.toString(), "--master",
                "local[2]", "--partitions", "2"));
        assertTrue(o.toString().startsWith("scored 4 runs (3 ok, 1 failed)"), o.toString());
        assertSameFolders(tmp.resolve("refdata-cli"), out);
    }

    /** Runs {@code trajeval suite MANIFEST --out tmp/NAME} in this JVM. */
    private static Path trajevalSuite(Path manifest, String name, String... more) {
        Path out = tmp.resolve(name);
        CommandLine cl = TrajevalCommand.newCommandLine();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(new StringWriter()));
        cl.setErr(new PrintWriter(err));
        String[] args = Stream.concat(Stream.of("suite", manifest.toString(), "--out", out.toString()),
                Stream.of(more)).toArray(String[]::new);
        assertEquals(0, cl.execute(args), err.toString());
        return out;
    }

    /** The same file names, and each file the same bytes. */
    private static void assertSameFolders(Path expected, Path actual) throws IOException {
        List<String> names = names(expected);
        assertEquals(names, names(actual));
        assertTrue(names.containsAll(SuiteReportFolder.FILES), names.toString());
        for (String n : names) {
            assertEquals(Files.readString(expected.resolve(n)), Files.readString(actual.resolve(n)), n);
        }
    }

    private static List<String> names(Path dir) throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(Files::isRegularFile).map(p -> p.getFileName().toString()).sorted().toList();
        }
    }
}
