package org.trajeval.core.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.protocol.MiniJsonSchema;
import org.trajeval.core.traj.PlanarTrajectory;

/** Every shape of the evaluation report conforms to docs/report.schema.json and reads back equal. */
class EvaluationReportSchemaTest {

    private static PlanarTrajectory path(double offset) {
        int n = 400;
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        for (int i = 0; i < n; i++) {
            t[i] = i * 0.1;
            x[i] = 0.8 * t[i] + offset;
            y[i] = Math.sin(0.2 * t[i]);
            yaw[i] = Math.atan2(0.2 * Math.cos(0.2 * t[i]), 0.8);
        }
        return PlanarTrajectory.of(t, x, y, yaw);
    }

    @Test
    void reportsOfEveryPathConformToTheSchemaAndRoundTrip() throws IOException {
        Path schemaFile = Paths.get(System.getProperty("trajeval.projectDir", "."), "..", "docs",
                "report.schema.json");
        ObjectMapper json = new ObjectMapper();
        MiniJsonSchema schema = new MiniJsonSchema(json.readTree(schemaFile.toFile()));
        LoadedTrajectory ref = new LoadedTrajectory("gt.csv", TrajectoryFormat.CSV, "given", path(0), "ab", false);
        LoadedTrajectory est = new LoadedTrajectory("est.csv", TrajectoryFormat.CSV, "given", path(0.1), "cd", false);
        List<EvaluationOptions> variants = List.of(
                EvaluationOptions.preset(Convention.LESSON),
                EvaluationOptions.preset(Convention.EVO),
                EvaluationOptions.preset(Convention.KITTI),
                EvaluationOptions.preset(Convention.EVO).withAssociation(AssociationMethod.NEAREST_INTERPOLATED)
                        .withAlignment(AlignmentModel.SIM2));
        for (EvaluationOptions o : variants) {
            EvaluationReport report = Evaluator.evaluate(ref, est, o);
            String text = ReportJson.toJson(report);
            JsonNode doc = json.readTree(text);
            List<String> problems = schema.check(doc);
            assertTrue(problems.isEmpty(), o.convention() + ": " + problems);
            assertEquals(text, ReportJson.toJson(ReportJson.parseEvaluation(text)), "round trip");
        }
    }

    @Test
    void reportOfArraysGivenThroughTheJavaApiConformsToTheSchema() throws IOException {
        Path schemaFile = Paths.get(System.getProperty("trajeval.projectDir", "."), "..", "docs",
                "report.schema.json");
        ObjectMapper json = new ObjectMapper();
        MiniJsonSchema schema = new MiniJsonSchema(json.readTree(schemaFile.toFile()));
        double[] t = {0, 1, 2, 3, 4};
        double[] x = {0, 1, 2, 3, 4};
        double[] y = {0, 0, 1, 1, 2};
        double[] yaw = {0, 0.1, 0.2, 0.3, 0.4};
        EvaluationReport report = org.trajeval.api.TrajectoryEvaluator.withDefaults().evaluate(
                org.trajeval.api.Poses.planar("truth", t, x, y, yaw), org.trajeval.api.Poses.planar("run", t, y, x, yaw));
        String text = ReportJson.toJson(report);
        List<String> problems = schema.check(json.readTree(text));
        assertTrue(problems.isEmpty(), problems.toString());
        assertEquals(text, ReportJson.toJson(ReportJson.parseEvaluation(text)), "round trip");
    }
}
