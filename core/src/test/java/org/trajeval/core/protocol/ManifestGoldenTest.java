package org.trajeval.core.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.metric.RpeUnit;

/** Manifests as golden file pairs: {@code name.yaml} + {@code name.expected.json}. */
class ManifestGoldenTest {
    private static final Path DIR = Path.of("src/test/resources/manifests");
    private static final ObjectMapper JSON = new ObjectMapper();

    @TestFactory
    Stream<DynamicTest> badManifestsAreRefusedWithTheKeyPath() throws IOException {
        return cases("bad").map(yaml -> DynamicTest.dynamicTest(yaml.getFileName().toString(), () -> {
            JsonNode expected = expected(yaml);
            InputException e = assertThrows(InputException.class, () -> new ManifestParser().read(yaml));
            assertEquals(InputProblem.valueOf(expected.get("problem").asText()), e.problem(), e.getMessage());
            assertEquals(expected.get("column").asText(), e.column(), e.getMessage());
            assertEquals(yaml.toString(), e.source());
            assertTrue(e.getMessage().contains("'" + e.column() + "'"), e.getMessage());
        }));
    }

    @TestFactory
    Stream<DynamicTest> hygieneFindingsMatchTheGoldenFiles() throws IOException {
        return cases("hygiene").map(yaml -> DynamicTest.dynamicTest(yaml.getFileName().toString(), () -> {
            JsonNode expected = expected(yaml);
            SuiteManifest m = new ManifestParser().read(yaml);
            List<String> leaks = SplitLeakage.find(SplitLeakage.assignments(m)).stream()
                    .map(SplitLeakage::describe).toList();
            assertEquals(strings(expected.get("leaks")), leaks);
            SeedSetCheck seeds = SeedSetCheck.of(m);
            List<Long> common = new ArrayList<>();
            expected.get("common").forEach(n -> common.add(n.asLong()));
            assertEquals(common, seeds.common());
            assertEquals(strings(expected.get("deviations")),
                    seeds.deviations().stream().map(SeedSetCheck.Deviation::describe).toList());
        }));
    }

    @Test
    void simRealDescriptionFieldsAndBudgetPolicyAreRead() {
        SuiteManifest m = new ManifestParser().read(DIR.resolve("good/sim_real.yaml"));
        org.trajeval.core.options.RunMetadata sim = m.sequence("corridor_sim").about();
        assertEquals("sim", sim.domain());
        assertEquals("gazebo", sim.simulator());
        assertEquals("corridor", sim.scenario());
        // factors sorted by name; the integer 1 is the level 1.0
        assertEquals(java.util.Map.of("friction", 1.0, "obstacle_density", 0.4), sim.factors());
        assertEquals("friction=1.0;obstacle_density=0.4", sim.factorsText());
        assertEquals("stereo+imu", sim.modality());
        assertEquals("simulator", sim.groundTruth());
        assertTrue(m.sequence("corridor_real").about().real());
        assertEquals("mocap", m.sequence("corridor_real").about().groundTruth());
        assertEquals(org.trajeval.core.options.RunMetadata.NONE, m.sequence("plain").about());
        assertEquals(FailureDefinition.BudgetPolicy.WARN, m.failure().budget());
        assertEquals(0.25, m.failure().breakdownRate(), 0.0);
        assertEquals("measured/resources.csv", m.resources());
    }

    @Test
    void withoutTheNewFieldsTheDefaultsHold() {
        SuiteManifest m = new ManifestParser().read(DIR.resolve("good/full.yaml"));
        assertEquals(FailureDefinition.BudgetPolicy.FAIL, m.failure().budget());
        assertEquals(0.5, m.failure().breakdownRate(), 0.0);
        assertNull(m.resources());
        assertNull(m.sequence("a1").about().domain());
    }

    @Test
    void goodManifestIsReadCompletely() {
        SuiteManifest m = new ManifestParser().read(DIR.resolve("good/full.yaml"));
        assertEquals("golden", m.name());
        assertEquals(List.of(1L, 2L, 3L), m.seeds());
        assertEquals(List.of(Split.VAL, Split.TEST), m.evaluatedSplits());
        assertEquals(3, m.sequences().size());
        assertEquals(List.of("outdoor", "night"), m.sequence("c1").tags());
        assertEquals("other/c1_2.tum", m.methods().get(1).estimateFor("c1", 2));
        assertEquals("runs/m1/a1/seed3.csv", m.methods().get(0).estimateFor("a1", 3));
        EvaluationOptions o = SettingsResolver.evaluationOptions(m.metrics(), DataKind.SPATIAL);
        assertEquals(Convention.LESSON, o.convention());
        assertEquals(AlignmentModel.SE2, o.alignment());
        assertEquals(2.0, o.rpeDelta(), 0.0);
        assertEquals(RpeUnit.SECONDS, o.rpeUnit());
        assertEquals(0.8, m.failure().minCoverage(), 0.0);
        assertEquals(0.75, m.score().terms().get(1).weight(), 0.0);
        assertEquals(new Budget("gpu", 8, 0.5, 8192), m.budget());
    }

    @Test
    void manifestErrorWording() {
        InputException e = assertThrows(InputException.class,
                () -> new ManifestParser().read(DIR.resolve("bad/unknown_method_key.yaml")));
        assertEquals(DIR.resolve("bad/unknown_method_key.yaml") + ": 'methods[1].estimate_files': unknown key; "
                + "expected one of estimates, name, seeds, settings", e.getMessage());
    }

    @Test
    void missingManifestIsUnreadable() {
        InputException e = assertThrows(InputException.class,
                () -> new ManifestParser().read(DIR.resolve("no-such.yaml")));
        assertEquals(InputProblem.UNREADABLE, e.problem());
        assertNull(e.column());
    }

    private static Stream<Path> cases(String sub) throws IOException {
        try (Stream<Path> s = Files.list(DIR.resolve(sub))) {
            return s.filter(p -> p.toString().endsWith(".yaml")).sorted().toList().stream();
        }
    }

    private static JsonNode expected(Path yaml) throws IOException {
        String name = yaml.getFileName().toString().replace(".yaml", ".expected.json");
        return JSON.readTree(yaml.resolveSibling(name).toFile());
    }

    private static List<String> strings(JsonNode array) {
        List<String> out = new ArrayList<>();
        array.forEach(n -> out.add(n.asText()));
        return out;
    }
}
