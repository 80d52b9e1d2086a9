package org.trajeval.pipeline.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.Statement;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.PipelineCommand;
import org.trajeval.pipeline.StandInScorer;
import org.trajeval.pipeline.bundle.RunManifest;
import org.trajeval.pipeline.kafka.RunEvent;
import org.trajeval.store.StoreLocation;

/** run.yaml and Kafka events carry a run's domain, scenario, factors, taxonomy and resources into the report and the store. */
class RunDescriptionTest {
    private static final String FIELDS = "domain: sim\nsimulator: gazebo\nscenario: c1\n"
            + "factors: {obstacle_density: 0.4}\nenvironment: warehouse\nmodality: [lidar, wheel]\n"
            + "ground_truth: simulator\nresources: {wall_time_s: 12.5, peak_memory_mib: 640, device: cpu}\n";

    @TempDir
    Path root;

    @Test
    void runYamlFieldsReachTheReportAndTheStoreColumns() throws Exception {
        Path b = Fixtures.folderBundle(root.resolve("incoming"), "r1", "r1", 30, 1);
        Fixtures.write(b.resolve("run.yaml"), Fixtures.manifest("r1", "bot-1", "gt.csv", "est.csv") + FIELDS);
        Fixtures.marker(root.resolve("incoming"), "r1");
        StringWriter out = new StringWriter();
        picocli.CommandLine cl = PipelineCommand.newCommandLine(c -> new StandInScorer(), Map.of());
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(out));
        assertEquals(0, cl.execute("watch", "--root", root.toString(), "--drain"), out.toString());
        com.fasterxml.jackson.databind.JsonNode report = new com.fasterxml.jackson.databind.ObjectMapper()
                .readTree(Files.readString(root.resolve("reports/r1.json")));
        assertEquals("sim", report.get("domain").asText());
        assertEquals("lidar+wheel", report.get("modality").asText());
        assertEquals(0.4, report.get("factors").get("obstacle_density").asDouble(), 0.0);
        assertEquals(12.5, report.get("resources").get("wall_time_s").asDouble(), 0.0);
        try (Connection c = DriverManager.getConnection(StoreLocation.sqlite(root.resolve("trajeval.db")).jdbcUrl());
                Statement s = c.createStatement();
                ResultSet rs = s.executeQuery("SELECT domain, scenario, simulator, environment, modality, ground_truth, "
                        + "factors, wall_time_s, peak_memory_mib FROM runs WHERE run_id = 'r1'")) {
            assertTrue(rs.next());
            assertEquals("sim", rs.getString(1));
            assertEquals("c1", rs.getString(2));
            assertEquals("gazebo", rs.getString(3));
            assertEquals("warehouse", rs.getString(4));
            assertEquals("lidar+wheel", rs.getString(5));
            assertEquals("simulator", rs.getString(6));
            assertEquals("obstacle_density=0.4", rs.getString(7));
            assertEquals(12.5, rs.getDouble(8), 0.0);
            assertEquals(640.0, rs.getDouble(9), 0.0);
        }
    }

    @Test
    void aKafkaEventCarriesTheSameFields() {
        RunEvent e = RunEvent.parse("{\"run_id\": \"r9\", \"bundle\": \"b/r9.zip\", \"domain\": \"real\", "
                + "\"scenario\": \"c1\", \"resources\": {\"wall_time_s\": 3.0, \"peak_memory_mib\": 100}}", "topic-0@5");
        assertEquals("real", e.metadata().about().domain());
        assertEquals(3.0, e.metadata().resources().wallTimeS(), 0.0);
    }

    @Test
    void malformedFieldsAreRefusedNamingTheField() throws Exception {
        Path file = root.resolve("run.yaml");
        for (String[] c : new String[][] {{"domain: simulated\n", "domain"},
            {"factors: {obstacle_density: high}\n", "factors.obstacle_density"},
            {"resources: {wall_time_s: 0, peak_memory_mib: 1}\n", "resources.wall_time_s"},
            {"resources: {wall_time_s: 1, peak_memory_mib: 1, gpu_hours: 2}\n", "resources.gpu_hours"},
            {"domain: real\nsimulator: carla\n", "simulator"}}) {
            Files.writeString(file, Fixtures.manifest("r1", "bot-1", "gt.csv", "est.csv") + c[0]);
            InputException e = assertThrows(InputException.class, () -> RunManifest.read(file, "b/run.yaml", 1 << 20));
            assertEquals(c[1], e.column(), e.getMessage());
        }
    }

    @Test
    void eachDescriptionFieldAloneIsReadAndNoneGivesNoDescription() throws Exception {
        // RunFields converts the tree for the description only when one of its keys is present: every key
        // must still be seen on its own (one case per RunField key and resources), and a run.yaml without
        // any must give the same empty description and no resources as before
        Path file = root.resolve("run.yaml");
        Map<String, String> alone = new java.util.LinkedHashMap<>();
        alone.put("domain", "domain: real\n");
        alone.put("simulator", "domain: sim\nsimulator: gazebo\n");
        alone.put("scenario", "scenario: c1\n");
        alone.put("factors", "factors: {obstacle_density: 0.4}\n");
        alone.put("environment", "environment: warehouse\n");
        alone.put("modality", "modality: [lidar, wheel]\n");
        alone.put("ground_truth", "ground_truth: simulator\n");
        assertEquals(new java.util.TreeSet<>(org.trajeval.core.options.RunField.keys()),
                new java.util.TreeSet<>(alone.keySet()), "one case per description key");
        for (Map.Entry<String, String> c : alone.entrySet()) {
            Files.writeString(file, Fixtures.manifest("r1", "bot-1", "gt.csv", "est.csv") + c.getValue());
            org.trajeval.core.options.RunMetadata about = RunManifest.read(file, "b/run.yaml", 1 << 20).metadata()
                    .about();
            assertTrue(!about.equals(org.trajeval.core.options.RunMetadata.NONE), c.getKey());
        }
        Files.writeString(file, Fixtures.manifest("r1", "bot-1", "gt.csv", "est.csv")
                + "resources: {wall_time_s: 2.5, peak_memory_mib: 64}\n");
        assertEquals(2.5, RunManifest.read(file, "b/run.yaml", 1 << 20).metadata().resources().wallTimeS(), 0.0);
        Files.writeString(file, Fixtures.manifest("r1", "bot-1", "gt.csv", "est.csv") + "site: lab\n");
        org.trajeval.pipeline.RunMetadata plain = RunManifest.read(file, "b/run.yaml", 1 << 20).metadata();
        assertEquals(org.trajeval.core.options.RunMetadata.NONE, plain.about());
        assertEquals(null, plain.resources());
    }
}
