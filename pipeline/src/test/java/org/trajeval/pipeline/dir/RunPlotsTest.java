package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.report.SavedEvaluation;
import org.trajeval.pipeline.CoreRunScorer;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.StandInScorer;

/** run.yaml {@code plot: true}: eval --plot's page beside the report, moved into place whole, never costing the run. */
class RunPlotsTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    @TempDir
    Path root;

    private static Path plotBundle(Path in, String name, String runId, String plot) {
        Path b = Fixtures.folderBundle(in, name, runId, 300, 1);
        Fixtures.write(b.resolve("run.yaml"), Fixtures.manifest(runId, "bot-1", "gt.csv", "est.csv")
                + (plot == null ? "" : "plot: " + plot + "\n"));
        Fixtures.marker(in, name);
        return b;
    }

    private static List<String> names(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.map(p -> p.getFileName().toString()).sorted().toList();
        }
    }

    @Test
    void plotTrueWritesTheEvalPlotPageBesideTheReportAndLeavesNoDraft() throws IOException {
        try (ServiceHarness h = new ServiceHarness(root, new CoreRunScorer(1 << 20))) {
            plotBundle(h.layout.incoming(), "b1", "run-1", "true");
            plotBundle(h.layout.incoming(), "b2", "run-2", null);
            assertEquals(0, h.service.drain().exitCode());
            Path plots = h.layout.reports().resolve("run-1.plots");
            assertTrue(Files.isRegularFile(plots.resolve("index.html")));
            for (String f : List.of("trajectories", "ate_trans", "rpe_rot", "hist_ate_trans", "subtraj_trans")) {
                assertTrue(Files.size(plots.resolve(f + ".svg")) > 1000, f);
                assertTrue(Files.size(plots.resolve(f + ".png")) > 1000, f);
            }
            // the page's numbers are the report's: the same ATE RMSE, as eval --plot writes it
            double rmse = JSON.readTree(h.layout.reports().resolve("run-1.json").toFile()).get("evaluation")
                    .get("ate").get("trans_m").get("rmse").asDouble();
            assertTrue(Files.readString(plots.resolve("index.html")).contains(String.format(java.util.Locale.ROOT,
                    "%.6g", rmse)));
            // off by default; no draft folder is left behind
            assertEquals(List.of("run-1.json", "run-1.plots", "run-2.json"), names(h.layout.reports()));
        }
    }

    @Test
    void aRunWhoseFiguresCannotBeDrawnIsReportedWithAWarning() throws IOException {
        // the stand-in scorer keeps no per-pose series: drawing fails, the run is reported all the same
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            plotBundle(h.layout.incoming(), "b1", "run-1", "true");
            assertEquals(0, h.service.drain().exitCode());
            JsonNode w = JSON.readTree(h.layout.reports().resolve("run-1.json").toFile()).get("evaluation")
                    .get("warnings");
            assertEquals("plot_failed", w.get(0).get("code").asText());
            assertTrue(w.get(0).get("message").asText().contains("no per-pose series"), w.toString());
            assertEquals(List.of("run-1.json"), names(h.layout.reports()));
        }
    }

    @Test
    void plotMustBeTrueOrFalse() throws IOException {
        try (ServiceHarness h = new ServiceHarness(root, new StandInScorer())) {
            plotBundle(h.layout.incoming(), "b1", "run-1", "yes please");
            h.service.drain();
            assertFalse(Files.exists(h.layout.reports().resolve("run-1.json")));
            String reason = Files.readString(h.layout.failed().resolve("b1.error.json"));
            assertTrue(reason.contains("'plot' must be true or false"), reason);
        }
    }

    @Test
    void aSecondContentOfTheRunGetsItsOwnFolder() throws IOException {
        try (ServiceHarness h = new ServiceHarness(root, new CoreRunScorer(1 << 20))) {
            plotBundle(h.layout.incoming(), "b1", "run-1", "true");
            h.service.drain();
            Path b2 = Fixtures.folderBundle(h.layout.incoming(), "b2", "run-1", 300, 2); // new content, same run id
            Fixtures.write(b2.resolve("run.yaml"), Fixtures.manifest("run-1", "bot-1", "gt.csv", "est.csv")
                    + "plot: true\n");
            Fixtures.marker(h.layout.incoming(), "b2");
            h.service.drain();
            assertTrue(Files.isRegularFile(h.layout.reports().resolve("run-1.v2.plots/index.html")));
            assertTrue(Files.isRegularFile(h.layout.reports().resolve("run-1.plots/index.html")));
        }
    }
}
