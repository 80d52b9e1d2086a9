package org.trajeval.core.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.RunEntry;
import org.trajeval.core.report.SuiteReportFiles;

/** The suite runner on the seeded demo benchmark, with the real readers and engine. */
class SuiteRunnerTest {
    private static ExecutorService pool;

    @TempDir
    static Path tmp;
    private static Path manifest;
    private static SuiteRunner.Result result;

    @BeforeAll
    static void runDemo() {
        pool = Executors.newFixedThreadPool(2);
        manifest = DemoBenchmark.write(tmp.resolve("bench"), 7);
        result = new SuiteRunner(RunEngine.standard(), pool, SuiteRunner.Progress.none())
                .run(manifest, SuiteRunner.Settings.defaults(1).withAllowLeakage(true));
    }

    @AfterAll
    static void stop() {
        pool.shutdownNow();
    }

    @Test
    void everyRunIsScoredAndTheFailureIsCountedNotDropped() {
        SuiteReport r = result.report();
        assertEquals(3 * 8 * 5, r.runs().size()); // methods x test sequences x seeds
        List<RunEntry> failed = r.runs().stream().filter(x -> !x.ok()).toList();
        assertEquals(1, failed.size());
        RunEntry f = failed.get(0);
        assertEquals("gamma", f.method());
        assertEquals("seq06", f.sequence());
        assertEquals(3, f.seed());
        assertEquals("low_coverage", f.failure().reason());
        assertEquals(0.0, f.score(), 0.0);
        SuiteReport.MethodSummary gamma = r.methods().get(2);
        assertEquals(40, gamma.runs());
        assertEquals(1, gamma.failures());
        assertTrue(gamma.failureRate().wilson().lower() > 0 && gamma.failureRate().wilson().upper() < 0.2);
    }

    @Test
    void leakageIsFlaggedWhenAllowed() {
        SuiteReport.Hygiene h = result.report().hygiene();
        assertTrue(h.leakageAllowed());
        assertEquals(1, h.leakage().size());
        assertEquals("s02", h.leakage().get(0).id());
        assertTrue(h.warnings().get(0).startsWith("LEAKAGE"));
    }

    @Test
    void leakageRefusesToRunByDefault() {
        SplitLeakageException e = assertThrows(SplitLeakageException.class, () -> new SuiteRunner(RunEngine.standard(),
                pool, SuiteRunner.Progress.none()).run(manifest, SuiteRunner.Settings.defaults(1)));
        assertEquals("s02", e.leaks().get(0).id());
        assertTrue(e.getMessage().contains("session s02: val {seq03}, test {seq11}"), e.getMessage());
    }

    @Test
    void methodsAreOrderedByQualityAsGenerated() {
        // alpha has the least drift and noise, gamma the most: paired ATE differences are negative
        SuiteReport r = result.report();
        SuiteReport.Comparison ab = r.comparisons().stream().filter(c -> c.methodA().equals("alpha")
                && c.methodB().equals("gamma") && c.metric().equals("ate_trans_rmse_m")).findFirst().orElseThrow();
        assertEquals(8, ab.n());
        assertTrue(ab.tInterval().upper() < 0, "alpha - gamma ATE interval " + ab.tInterval());
        assertTrue(ab.bootstrap().upper() < 0);
        assertEquals("exact", ab.wilcoxon().method());
        assertEquals(2.0 / 256.0, ab.wilcoxon().pValue(), 1e-12); // all 8 differences negative
    }

    @Test
    void reportIsIndependentOfTheThreadCountAndByteIdentical() {
        ExecutorService one = Executors.newSingleThreadExecutor();
        try {
            SuiteRunner.Result again = new SuiteRunner(RunEngine.standard(), one, SuiteRunner.Progress.none())
                    .run(manifest, SuiteRunner.Settings.defaults(1).withAllowLeakage(true));
            assertEquals(SuiteReportFiles.toJson(result.report()), SuiteReportFiles.toJson(again.report()));
        } finally {
            one.shutdownNow();
        }
        String json = SuiteReportFiles.toJson(result.report());
        assertFalse(json.contains(tmp.toString()), "report.json must not hold absolute paths");
        assertFalse(json.contains("NaN"));
    }

    @Test
    void reportRoundTripsThroughJson() {
        String json = SuiteReportFiles.toJson(result.report());
        SuiteReport back = SuiteReportFiles.parse(json, "report.json");
        assertEquals(json, SuiteReportFiles.toJson(back));
    }

    @Test
    void inputsCarryTheirDigests() {
        SuiteReport r = result.report();
        assertEquals("manifest", r.inputs().stream().filter(i -> i.path().equals("suite.yaml")).findFirst()
                .orElseThrow().role());
        assertEquals(1 + 8 + 120, r.inputs().size());
        assertTrue(r.inputs().stream().allMatch(i -> i.sha256().matches("[0-9a-f]{64}")));
    }

    @Test
    void missingEstimateIsAFailureAndProgressIsReported() throws IOException {
        Path bench = tmp.resolve("missing");
        Path m = DemoBenchmark.write(bench, 7);
        Files.delete(bench.resolve("runs/beta/seq04/seed2.csv"));
        Files.writeString(bench.resolve("runs/beta/seq05/seed2.csv"), "t,x,y,yaw\n0,1,2\n");
        AtomicInteger calls = new AtomicInteger();
        SuiteRunner.Result res = new SuiteRunner(RunEngine.standard(), pool, (done, total) -> calls.incrementAndGet())
                .run(m, SuiteRunner.Settings.defaults(1).withAllowLeakage(true));
        assertEquals(120, calls.get());
        RunEntry missing = find(res.report(), "beta", "seq04", 2);
        assertEquals("missing_estimate", missing.failure().reason());
        assertNull(missing.evaluation());
        assertEquals("unreadable_estimate", find(res.report(), "beta", "seq05", 2).failure().reason());
        assertEquals(2, res.report().methods().get(1).failures());
    }

    @Test
    void seedDeviationRestrictsStatisticsToTheCommonSet() throws IOException {
        Path bench = tmp.resolve("seeds");
        Path m = DemoBenchmark.write(bench, 7);
        String text = Files.readString(m).replace("- {name: beta, estimates: \"runs/{method}/{sequence}/seed{seed}.csv\"}",
                "- {name: beta, estimates: \"runs/{method}/{sequence}/seed{seed}.csv\", seeds: [1, 2, 3, 4]}");
        Files.writeString(m, text);
        SuiteRunner.Result res = new SuiteRunner(RunEngine.standard(), pool, SuiteRunner.Progress.none())
                .run(m, SuiteRunner.Settings.defaults(1).withAllowLeakage(true));
        assertEquals(List.of(1L, 2L, 3L, 4L), res.report().protocol().seeds().common());
        assertEquals(3 * 8 * 4, res.report().runs().size());
        assertTrue(res.report().hygiene().warnings().stream().anyMatch(w -> w.contains("method beta: missing seeds [5]")));
    }

    @Test
    void referenceOutsideTheFolderThroughASymlinkIsRefused() throws IOException {
        Path bench = tmp.resolve("link");
        Path m = DemoBenchmark.write(bench, 7);
        Path outside = tmp.resolve("outside.csv");
        Files.copy(bench.resolve("data/seq04/reference.csv"), outside);
        Files.delete(bench.resolve("data/seq04/reference.csv"));
        Files.createSymbolicLink(bench.resolve("data/seq04/reference.csv"), outside);
        InputException e = assertThrows(InputException.class, () -> new SuiteRunner(RunEngine.standard(), pool,
                SuiteRunner.Progress.none()).run(m, SuiteRunner.Settings.defaults(1).withAllowLeakage(true)));
        assertEquals(InputProblem.PATH_ESCAPES, e.problem());
        assertEquals("sequences[3].reference", e.column());
    }

    @Test
    void plotsHaveOneTracePerMethodAndSeedPerSequenceOnRelativeTime() {
        assertEquals(8, result.plots().size());
        result.plots().forEach(p -> assertEquals(3 * 5, p.estimates().size())); // 3 methods, 5 common seeds
        result.plots().forEach(p -> assertEquals("s", p.timeUnit()));
        // times count from the reference's first stamp, not from the Unix epoch
        double t0 = result.plots().get(0).estimates().get(0).t()[0];
        assertTrue(t0 >= 0 && t0 < 1.0, "first time " + t0);
        // error of the plotted alpha run is small: its drift is 6 mm/s over 60 s
        double[] e = result.plots().get(0).estimates().get(0).errorM();
        assertNotNull(e);
        assertTrue(java.util.Arrays.stream(e).filter(Double::isFinite).max().orElseThrow() < 1.0);
    }

    @Test
    void reportConformsToTheDocumentedSchema() throws IOException {
        com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
        Path schemaFile = Path.of(System.getProperty("trajeval.projectDir", "."), "..", "docs",
                "suite-report.schema.json");
        MiniJsonSchema schema = new MiniJsonSchema(json.readTree(schemaFile.toFile()));
        assertEquals(List.of(), schema.check(json.readTree(SuiteReportFiles.toJson(result.report()))));
        // and the checker is not blind: a report without its runs is refused
        com.fasterxml.jackson.databind.node.ObjectNode broken =
                (com.fasterxml.jackson.databind.node.ObjectNode) json.readTree(SuiteReportFiles.toJson(result.report()));
        broken.remove("runs");
        broken.put("extra", 1);
        assertEquals(2, schema.check(broken).size());
    }

    private static RunEntry find(SuiteReport r, String method, String seq, long seed) {
        return r.runs().stream().filter(x -> x.method().equals(method) && x.sequence().equals(seq)
                && x.seed() == seed).findFirst().orElseThrow();
    }
}
