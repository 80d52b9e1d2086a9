package org.trajeval.core.protocol;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.ObjectInputStream;
import java.io.ObjectOutputStream;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.RefData;
import org.trajeval.core.report.SequencePlot;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReportFiles;

/**
 * The suite runner split into planning, per-run scoring and analysis writes what the runner wrote
 * before the split ({@link PreSplitSuiteRunner}, the oracle), on the seeded demo suite and on a
 * suite of the real reference data; and the split steps composed by hand, with every task and
 * result through Java serialisation and the runs scored in reverse order (as a cluster would
 * ship and return them), give the same report again. report.json holds no timing or host field,
 * so the files are compared whole.
 */
class SuiteSplitTest {
    private static ExecutorService pool;

    @TempDir
    static Path tmp;

    @BeforeAll
    static void start() {
        pool = Executors.newFixedThreadPool(2);
    }

    @AfterAll
    static void stop() {
        pool.shutdownNow();
    }

    @Test
    void demoSuiteWritesTheSameFilesAsBeforeTheSplit() {
        Path manifest = DemoBenchmark.write(tmp.resolve("demo"), 7);
        assertSameAsBeforeTheSplit(manifest, SuiteRunner.Settings.defaults(1).withAllowLeakage(true));
    }

    @Test
    void refdataSuiteWritesTheSameFilesAsBeforeTheSplitWithItsFailedRun() {
        Path manifest = RefdataSuite.write(tmp.resolve("refdata"), RefData.dir());
        SuiteReport r = assertSameAsBeforeTheSplit(manifest, SuiteRunner.Settings.defaults(1));
        SuiteReport.RunEntry missing = r.runs().stream().filter(x -> !x.ok()).findFirst().orElseThrow();
        assertEquals("rgbdslam", missing.method());
        assertEquals("fr2_desk", missing.sequence());
        assertEquals("missing_estimate", missing.failure().reason());
        assertEquals(3, r.runs().stream().filter(SuiteReport.RunEntry::ok).count());
    }

    @Test
    void splitStepsThroughSerialisationInAnyOrderGiveTheRunnersReport() throws Exception {
        Path manifest = DemoBenchmark.write(tmp.resolve("shipped"), 7);
        SuiteRunner.Settings settings = SuiteRunner.Settings.defaults(1).withAllowLeakage(true);
        SuiteRunner.Result runner = new SuiteRunner(RunEngine.standard(), pool, SuiteRunner.Progress.none())
                .run(manifest, settings);

        SuiteManifest m = new ManifestParser().read(manifest);
        SuitePlan plan = SuitePlan.of(m, manifest, settings, new RunScorer(RunEngine.standard(), m, manifest));
        // a worker parses the manifest itself and reads the references it needs
        SuiteManifest onWorker = new ManifestParser().read(manifest);
        RunScorer worker = new RunScorer(RunEngine.standard(), onWorker, manifest);
        RunResult[] results = new RunResult[plan.tasks().size()];
        List<RunTask> reversed = new ArrayList<>(plan.tasks());
        Collections.reverse(reversed);
        for (RunTask t : reversed) {
            RunTask shipped = roundTrip(t);
            results[shipped.index()] = roundTrip(worker.score(shipped, worker.reference(shipped.sequence())));
        }
        SuiteRunner.Result split = SuiteAssembly.assemble(plan, List.of(results), settings);
        assertEquals(SuiteReportFiles.toJson(runner.report()), SuiteReportFiles.toJson(split.report()));
        assertSamePlots(runner.plots(), split.plots());
    }

    @Test
    void resultsOutOfTaskOrderAreRefused() {
        Path manifest = RefdataSuite.write(tmp.resolve("order"), RefData.dir());
        SuiteRunner.Settings settings = SuiteRunner.Settings.defaults(1);
        SuiteManifest m = new ManifestParser().read(manifest);
        RunScorer scorer = new RunScorer(RunEngine.standard(), m, manifest);
        SuitePlan plan = SuitePlan.of(m, manifest, settings, scorer);
        List<RunResult> results = new ArrayList<>();
        for (RunTask t : plan.tasks()) {
            results.add(scorer.score(t, plan.references().get(t.sequence())));
        }
        Collections.swap(results, 0, 1);
        assertThrows(IllegalArgumentException.class, () -> SuiteAssembly.assemble(plan, results, settings));
    }

    @Test
    void aDetectMetricTheSuiteDoesNotCompareIsRefusedBeforeAnyRunIsScored() {
        Path manifest = RefdataSuite.write(tmp.resolve("detect"), RefData.dir());
        SuiteRunner.Settings settings = new SuiteRunner.Settings(1, false, 0.95, 4000, 0.8,
                Map.of("drift_trans_pct", 1.0));
        InputException e = assertThrows(InputException.class, () -> new SuiteRunner(RunEngine.standard(), pool,
                (done, total) -> {
                    throw new AssertionError("a run was scored");
                }).run(manifest, settings));
        assertEquals("--detect", e.column());
    }

    private static SuiteReport assertSameAsBeforeTheSplit(Path manifest, SuiteRunner.Settings settings) {
        SuiteRunner.Result before = new PreSplitSuiteRunner(RunEngine.standard(), pool, SuiteRunner.Progress.none())
                .run(manifest, settings);
        SuiteRunner.Result after = new SuiteRunner(RunEngine.standard(), pool, SuiteRunner.Progress.none())
                .run(manifest, settings);
        assertEquals(SuiteReportFiles.toJson(before.report()), SuiteReportFiles.toJson(after.report()));
        assertEquals(SuiteReportFiles.runsCsv(before.report()), SuiteReportFiles.runsCsv(after.report()));
        assertEquals(SuiteReportFiles.methodsCsv(before.report()), SuiteReportFiles.methodsCsv(after.report()));
        assertEquals(SuiteReportFiles.comparisonsCsv(before.report()),
                SuiteReportFiles.comparisonsCsv(after.report()));
        assertSamePlots(before.plots(), after.plots());
        return after.report();
    }

    private static void assertSamePlots(List<SequencePlot> a, List<SequencePlot> b) {
        assertEquals(a.size(), b.size());
        for (int i = 0; i < a.size(); i++) {
            SequencePlot p = a.get(i);
            SequencePlot q = b.get(i);
            assertEquals(p.sequence(), q.sequence());
            assertEquals(p.timeUnit(), q.timeUnit());
            assertArrayEquals(p.referenceX(), q.referenceX());
            assertArrayEquals(p.referenceY(), q.referenceY());
            assertArrayEquals(p.referenceZ(), q.referenceZ());
            assertEquals(p.estimates().size(), q.estimates().size());
            for (int j = 0; j < p.estimates().size(); j++) {
                SequencePlot.Trace s = p.estimates().get(j);
                SequencePlot.Trace t = q.estimates().get(j);
                assertEquals(s.method() + s.seed() + s.alignment(), t.method() + t.seed() + t.alignment());
                assertArrayEquals(s.x(), t.x());
                assertArrayEquals(s.y(), t.y());
                assertArrayEquals(s.z(), t.z());
                assertArrayEquals(s.t(), t.t());
                assertArrayEquals(s.errorM(), t.errorM());
            }
        }
    }

    @SuppressWarnings("unchecked")
    private static <T> T roundTrip(T value) throws IOException, ClassNotFoundException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (ObjectOutputStream out = new ObjectOutputStream(bytes)) {
            out.writeObject(value);
        }
        try (ObjectInputStream in = new ObjectInputStream(new ByteArrayInputStream(bytes.toByteArray()))) {
            return (T) in.readObject();
        }
    }
}
