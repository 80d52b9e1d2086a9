package org.trajeval.pipeline.store;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.PipelineCommand;
import org.trajeval.pipeline.RunLabels;
import org.trajeval.pipeline.StandInScorer;
import org.trajeval.pipeline.bundle.RunManifest;
import org.trajeval.pipeline.kafka.RunEvent;
import org.trajeval.store.ResultsStore;
import org.trajeval.store.RunRecord;
import org.trajeval.store.Selection;
import org.trajeval.store.StoreLocation;
import picocli.CommandLine;

/** run.yaml and Kafka events carry site, software_version and tags into the report and the store. */
class RunLabelsTest {
    private static final String LABELS = "site: hamburg\nsoftware_version: \"2.10\"\ntags: {shift: night, lane: 3}\n";

    @TempDir
    Path root;

    private void drain() {
        StringWriter out = new StringWriter();
        CommandLine cl = PipelineCommand.newCommandLine(c -> new StandInScorer(), Map.of());
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(out));
        assertEquals(0, cl.execute("watch", "--root", root.toString(), "--drain"), out.toString());
    }

    private void bundle(String name, String labels) {
        Path b = Fixtures.folderBundle(root.resolve("incoming"), name, name, 30, 1);
        Fixtures.write(b.resolve("run.yaml"), Fixtures.manifest(name, "bot-1", "gt.csv", "est.csv") + labels);
        Fixtures.marker(root.resolve("incoming"), name);
    }

    @Test
    void runYamlLabelsReachTheReportAndTheStoreColumnsAndTags() throws Exception {
        bundle("r1", LABELS);
        bundle("r2", "site: bremen\nsoftware_version: \"2.9\"\n");
        drain();
        com.fasterxml.jackson.databind.JsonNode report = new com.fasterxml.jackson.databind.ObjectMapper()
                .readTree(Files.readString(root.resolve("reports/r1.json")));
        assertEquals("hamburg", report.get("site").asText());
        assertEquals("2.10", report.get("software_version").asText());
        assertEquals("{\"lane\":\"3\",\"shift\":\"night\"}", report.get("tags").toString());
        try (ResultsStore s = ResultsStore.open(StoreLocation.sqlite(root.resolve("trajeval.db")),
                Clock.systemUTC())) {
            List<RunRecord> hamburg = s.select(Selection.parse("site=hamburg", "--where"));
            assertEquals(List.of("r1"), hamburg.stream().map(RunRecord::runId).toList());
            RunRecord r = hamburg.get(0);
            assertEquals("2.10", r.softwareVersion());
            assertEquals(Map.of("shift", "night", "lane", "3"), r.tags());
            assertEquals(List.of("r2"), s.select(Selection.parse("version=2.9", "--baseline")).stream()
                    .map(RunRecord::runId).toList());
            assertEquals(List.of("r1"), s.select(Selection.parse("shift=night", "--where")).stream()
                    .map(RunRecord::runId).toList());
        }
    }

    @Test
    void anInlineKafkaEventCarriesTheSameLabelsABundleEventTakesItsRunYamls() {
        String inline = "{\"run_id\": \"r9\", \"reference\": {\"file_name\": \"gt.csv\", \"data\": \"t,x,y,yaw\"}, "
                + "\"estimate\": {\"file_name\": \"est.csv\", \"data\": \"t,x,y,yaw\"}, \"site\": \"hamburg\", "
                + "\"software_version\": \"2.10\", \"tags\": {\"shift\": \"night\", \"lane\": 3}}";
        RunEvent e = RunEvent.parse(inline, "topic-0@5");
        assertEquals(new RunLabels("hamburg", "2.10", Map.of("shift", "night", "lane", "3")), e.metadata().labels());
        // a bundle's labels are its run.yaml's (as its metrics are): one in the event would be lost, so it is refused
        InputException bundle = assertThrows(InputException.class, () -> RunEvent.parse(
                "{\"run_id\": \"r9\", \"bundle\": \"b/r9.zip\", \"site\": \"hamburg\"}", "topic-0@6"));
        assertEquals("site", bundle.column());
    }

    private InputException refused(String labels) throws Exception {
        Path file = root.resolve("run.yaml");
        Files.writeString(file, Fixtures.manifest("r1", "bot-1", "gt.csv", "est.csv") + labels);
        return assertThrows(InputException.class, () -> RunManifest.read(file, "b/run.yaml", 1 << 20));
    }

    @Test
    void anUnquotedFractionalVersionATagNamedLikeAFieldAndNonMappingTagsAreRefused() throws Exception {
        // YAML reads 2.10 as the number 2.1: refused instead of silently stored as "2.1"
        InputException version = refused("software_version: 2.10\n");
        assertEquals("software_version", version.column());
        assertTrue(version.getMessage().contains("quote it"), version.getMessage());
        InputException reserved = refused("tags: {site: x}\n");
        assertEquals("tags.site", reserved.column());
        assertEquals("tags", refused("tags: [a, b]\n").column());
        assertEquals("tags.deep", refused("tags: {deep: {x: 1}}\n").column());
        assertEquals("b/run.yaml", refused("site: [x]\n").source());
    }
}
