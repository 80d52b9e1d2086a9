package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.protocol.DemoBenchmark;

/** suite, compare and splits check as a user runs them: output, exit codes, error lines. */
class SuiteCommandsTest {
    @TempDir
    static Path dir;
    private static Path manifest;
    private static Path report;

    @BeforeAll
    static void suite() {
        manifest = DemoBenchmark.write(dir.resolve("bench"), 7);
        CliRun r = CliRun.of("suite", manifest.toString(), "--out", dir.resolve("out").toString(), "--allow-leakage",
                "--threads", "2", "--resamples", "1000");
        assertEquals(0, r.code(), r.err());
        report = dir.resolve("out/report.json");
    }

    @Test
    void suiteWritesEveryReportFile() {
        for (String f : new String[] {"report.json", "runs.csv", "methods.csv", "comparisons.csv", "report.html",
            "ranks_score.svg", "ranks_ate_trans_rmse_m.svg"}) {
            assertTrue(Files.isRegularFile(dir.resolve("out").resolve(f)), f);
        }
        // every figure of the page also as a vector PDF beside its SVG, for a paper
        Path figures = dir.resolve("out").resolve(org.trajeval.figures.SuiteHtml.FIGURES);
        try (java.util.stream.Stream<Path> s = Files.list(figures)) {
            java.util.List<String> svgs = s.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".svg")).toList();
            assertTrue(!svgs.isEmpty());
            for (String svg : svgs) {
                assertTrue(Files.isRegularFile(figures.resolve(svg.replaceFirst("svg$", "pdf"))), svg);
            }
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    @Test
    void suiteRefusesLeakageWithExitCodeThree() {
        CliRun r = CliRun.of("suite", manifest.toString(), "--out", dir.resolve("refused").toString());
        assertEquals(ExitCodes.LEAKAGE, r.code());
        assertTrue(r.err().contains("session s02: val {seq03}, test {seq11}"), r.err());
        assertTrue(!Files.exists(dir.resolve("refused/report.json")));
    }

    @Test
    void badManifestGivesOneLineWithTheKeyPath() throws IOException {
        Path bad = dir.resolve("bench/bad.yaml");
        Files.writeString(bad, Files.readString(manifest).replace("name: trajeval-demo", "name: trajeval-demo\ncolour: red"));
        CliRun r = CliRun.of("suite", bad.toString(), "--out", dir.resolve("bad").toString());
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().contains("'colour': unknown key"), r.err());
    }

    @Test
    void suiteRefusesAnOutFolderWhereItWouldOverwriteATrajectoryOfTheManifest() throws IOException {
        // seq01's reference is moved to collide/runs.csv; --out collide would replace it with the runs table
        Path collide = Files.createDirectories(dir.resolve("bench/collide"));
        Files.copy(dir.resolve("bench/data/seq01/reference.csv"), collide.resolve("runs.csv"));
        byte[] before = Files.readAllBytes(collide.resolve("runs.csv"));
        Path edited = dir.resolve("bench/collide.yaml");
        Files.writeString(edited, Files.readString(manifest).replace("reference: data/seq01/reference.csv",
                "reference: collide/runs.csv"));
        CliRun r = CliRun.of("suite", edited.toString(), "--out", collide.toString(), "--allow-leakage");
        assertEquals(ExitCodes.BAD_INPUT, r.code(), r.err());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().contains("runs.csv: --out would overwrite the input"), r.err());
        assertTrue(java.util.Arrays.equals(before, Files.readAllBytes(collide.resolve("runs.csv"))));
        assertTrue(!Files.exists(collide.resolve("report.json")));
    }

    @Test
    void compareTwoMethodsOfOneReport() throws IOException {
        CliRun r = CliRun.of("compare", report.toString(), "-a", "alpha", "-b", "gamma", "--json");
        assertEquals(0, r.code(), r.err());
        JsonNode cs = new ObjectMapper().readTree(r.out());
        assertEquals(3, cs.size()); // two score metrics and the score
        assertEquals("ate_trans_rmse_m", cs.get(0).get("metric").asText());
        assertEquals(8, cs.get(0).get("n").asInt());
        assertTrue(cs.get(0).get("t_interval").get("upper").asDouble() < 0);
        assertEquals(8, cs.get(0).get("nonzero_differences").asInt());
        assertEquals("wilcoxon_exact", cs.get(0).get("test").asText());
        assertEquals(1, cs.get(0).get("holm").get("m").asInt()); // compare: a family of one test per metric
        assertEquals("exact", cs.get(0).get("hodges_lehmann").get("method").asText());
        CliRun table = CliRun.of("compare", report.toString(), "-a", "alpha", "-b", "gamma", "--detect",
                "ate_trans_rmse_m=0.05");
        // one test label per row, not one line for all
        assertEquals(3, table.out().lines().filter(l -> l.startsWith("alpha") && l.endsWith("Wilcoxon exact")).count(),
                table.out());
        assertTrue(table.out().contains("on ate_trans_rmse_m: detecting a mean difference of 0.05 needs"), table.out());
        CliRun unknown = CliRun.of("compare", report.toString(), "-a", "alpha", "-b", "gamma", "--detect", "speed=1");
        assertEquals(ExitCodes.BAD_INPUT, unknown.code());
        assertTrue(unknown.err().contains("--detect: the reports have no compared metric 'speed'"), unknown.err());
    }

    @Test
    void compareTwoReportsPairsTheSameMethodByLabel() {
        CliRun r = CliRun.of("compare", report.toString(), report.toString(), "-a", "beta", "-b", "beta", "--json");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("\"method_a\" : \"beta@A\""), r.out());
        assertTrue(r.out().contains("\"mean_difference\" : 0.0"), r.out()); // a report against itself
    }

    @Test
    void compareRefusesAnUnknownMethod() {
        CliRun r = CliRun.of("compare", report.toString(), "-a", "alpha", "-b", "delta");
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        assertTrue(r.err().contains("no method 'delta'"), r.err());
    }

    @Test
    void splitsCheckFindsTheLeakAndExitsWithThree() {
        CliRun r = CliRun.of("splits", "check", manifest.resolveSibling("splits.csv").toString());
        assertEquals(ExitCodes.LEAKAGE, r.code(), r.err());
        assertTrue(r.out().contains("session s02: val {seq03}, test {seq11}"), r.out());
    }

    @Test
    void splitsCheckOfTheLessonsTableFlagsSequenceS02() throws IOException {
        // the lesson's make_demo_data table: S02 is in train and in test
        Path t = dir.resolve("lesson_splits.csv");
        Files.writeString(t, "sequence_id,split\nS01,train\nS02,train\nS03,val\nS02,test\nS04,test\n");
        CliRun r = CliRun.of("splits", "check", t.toString());
        assertEquals(ExitCodes.LEAKAGE, r.code());
        assertTrue(r.out().contains("session S02: train {S02}, test {S02}"), r.out());
        assertTrue(r.out().contains("sequence S02: train {S02}, test {S02}"), r.out());
    }

    @Test
    void splitsCheckOfACleanTableExitsWithZero() throws IOException {
        Path t = dir.resolve("clean.csv");
        Files.writeString(t, "sequence_id,session_id,split\na,s1,train\nb,s1,train\nc,s2,test\n");
        CliRun r = CliRun.of("splits", "check", t.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().startsWith("no leakage: 3 rows, 2 sessions"), r.out());
    }

    @Test
    void splitsCheckOfABadTableNamesTheLine() throws IOException {
        Path t = dir.resolve("bad.csv");
        Files.writeString(t, "sequence_id,split\na,train\nb,holdout\n");
        CliRun r = CliRun.of("splits", "check", t.toString());
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        assertTrue(r.err().contains(t + ":3: column 'split' must be train, val or test, found \"holdout\""), r.err());
    }
}
