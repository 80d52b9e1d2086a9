package org.trajeval.core.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.report.BudgetReport;
import org.trajeval.core.report.DomainGapReport;
import org.trajeval.core.report.FactorSweep;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReportFiles;

/** The sim-real demo's report shows what the demo builds in: a flip, a breakdown, a budget failure. */
class SimRealDemoTest {
    @TempDir
    static Path dir;
    private static ExecutorService pool;
    private static SuiteReport report;

    @BeforeAll
    static void runTheDemo() {
        pool = Executors.newFixedThreadPool(2);
        Path manifest = SimRealDemo.write(dir.resolve("benchmark"), 7);
        report = new SuiteRunner(RunEngine.standard(), pool, SuiteRunner.Progress.none())
                .run(manifest, new SuiteRunner.Settings(7, false, 0.95, 1000)).report();
    }

    @AfterAll
    static void stop() {
        pool.shutdownNow();
    }

    @Test
    void alphaIsBestInSimulationAndBetaInRealityAFlipSupportedOnBothSides() {
        DomainGapReport g = report.domainGap();
        assertNotNull(g);
        assertEquals(DomainGap.PAIRED, g.intervalMethod());
        DomainGapReport.MetricGap ate = g.metrics().get(0);
        assertEquals("ate_trans_rmse_m", ate.metric());
        assertEquals(1, ate.flips().size());
        DomainGapReport.Flip f = ate.flips().get(0);
        assertEquals("alpha", f.betterInSim());
        assertEquals("beta", f.betterInReal());
        assertTrue(f.supported());
        // alpha's drift grows 7.5-fold from sim to real, beta's 1.4-fold: alpha's gap exceeds beta's
        assertTrue(f.gapDifferenceInterval().lower() > 0.0, f.toString());
    }

    @Test
    void gammaBreaksDownAtDensitySixTenthsTheOthersNever() {
        FactorSweep s = report.factorSweeps().get(0);
        assertEquals("obstacle_density", s.factor());
        assertEquals(List.of(0.0, 0.2, 0.4, 0.6, 0.8), s.levels());
        assertNull(s.methods().get(0).breakdownLevel());
        assertNull(s.methods().get(1).breakdownLevel());
        // gamma loses tracking on 2 of 3 seeds at 0.6 (rate 2/3 >= 0.5) and on all at 0.8
        assertEquals(0.6, s.methods().get(2).breakdownLevel(), 0.0);
        assertEquals(2, s.methods().get(2).levels().get(3).failures());
    }

    @Test
    void betasSlowRunFailsOnTheBudgetAndGammasUnmeasuredRunsAreUnknown() {
        BudgetReport b = report.budgets();
        assertEquals(3, b.unknownRuns());
        SuiteReport.RunEntry slow = report.runs().stream().filter(r -> r.method().equals("beta")
                && r.sequence().equals("c3_real") && r.seed() == 2).findFirst().orElseThrow();
        assertEquals("budget", slow.failure().reason());
        assertTrue(slow.failure().detail().startsWith("real-time factor 0.25 below"), slow.failure().detail());
        assertEquals(1, b.methods().get(1).over());
        String runs = SuiteReportFiles.runsCsv(report);
        assertTrue(runs.contains(",over,119.6,"), runs.lines().filter(l -> l.contains("c3_real")).toList().toString());
        assertTrue(runs.lines().findFirst().orElseThrow().endsWith("budget_status,wall_time_s,peak_memory_mib,"
                + "real_time_factor,budget_detail"));
    }

    @Test
    void theNewSectionsConformToTheDocumentedSchema() throws java.io.IOException {
        com.fasterxml.jackson.databind.ObjectMapper json = new com.fasterxml.jackson.databind.ObjectMapper();
        Path schemaFile = Path.of(System.getProperty("trajeval.projectDir", "."), "..", "docs",
                "suite-report.schema.json");
        MiniJsonSchema schema = new MiniJsonSchema(json.readTree(schemaFile.toFile()));
        assertEquals(List.of(), schema.check(json.readTree(SuiteReportFiles.toJson(report))));
    }

    @Test
    void slicesCoverEveryDescribedValue() {
        Map<String, Long> perDimension = report.slices().stream().collect(java.util.stream.Collectors.groupingBy(
                org.trajeval.core.report.SliceReport::dimension, java.util.stream.Collectors.counting()));
        // domain sim/real, environment campus/warehouse, modality lidar+wheel, ground truth 3 sources
        assertEquals(Map.of("domain", 2L, "environment", 2L, "modality", 1L, "ground_truth", 3L), perDimension);
    }
}
