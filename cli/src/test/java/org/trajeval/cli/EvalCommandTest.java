package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;

/** The eval command as a user runs it: options, output forms, exit codes, error lines. */
class EvalCommandTest {
    @TempDir
    Path dir;

    private Path csv(String name, String body) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, body.getBytes(StandardCharsets.UTF_8));
        return p;
    }

    /** A straight line at 1 m/s sampled at 10 Hz for 10 s; the estimate is 0.1 m to the left. */
    private Path[] offsetPair() throws IOException {
        StringBuilder gt = new StringBuilder("t,x,y,yaw\n");
        StringBuilder est = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i <= 100; i++) {
            double t = i * 0.1;
            gt.append(t).append(',').append(t).append(",0,0\n");
            est.append(t).append(',').append(t).append(",0.1,0\n");
        }
        return new Path[] {csv("gt.csv", gt.toString()), csv("est.csv", est.toString())};
    }

    @Test
    void jsonReportCarriesTheDocumentedKeysAndUnits() throws IOException {
        Path[] p = offsetPair();
        CliRun r = CliRun.of("eval", p[0].toString(), p[1].toString(), "--align", "none", "--json");
        assertEquals(0, r.code(), r.err());
        EvaluationReport rep = ReportJson.parseEvaluation(r.out());
        // 0.1 m to the left everywhere: ATE = 0.1 m by hand
        assertEquals(0.1, rep.ate().transM().rmse(), 1e-12);
        assertEquals(101, rep.association().matched());
        assertEquals("interpolate", rep.association().method());
        assertEquals("s", rep.rpe().unit());
        assertEquals(EvaluationReport.SCHEMA_VERSION, rep.schemaVersion());
        for (String key : new String[] {"\"trans_m\"", "\"rot_rad\"", "\"max_gap_s\"", "\"interp_error_bound_m\"",
            "\"sha256\"", "\"convention\"", "\"version\"", "\"pairs\"", "\"translation_m\""}) {
            assertTrue(r.out().contains(key), key);
        }
    }

    @Test
    void outWritesTheJsonFileAndStillPrintsTheTable() throws IOException {
        Path[] p = offsetPair();
        Path out = dir.resolve("reports/r.json");
        CliRun r = CliRun.of("eval", p[0].toString(), p[1].toString(), "--out", out.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("ATE trans (m)"));
        EvaluationReport rep = ReportJson.parseEvaluation(Files.readString(out));
        assertEquals("se2", rep.alignment().model());
        try (var s = Files.list(out.getParent())) {
            assertEquals(1, s.count(), "no temporary file left beside the report");
        }
    }

    @Test
    void badInputGivesExitCode2AndOneLineWithoutStackTrace() throws IOException {
        Path[] p = offsetPair();
        Path gt = csv("bad.csv", "t,x,y,yaw\n0,0,0,0\n1,1,0,nan\n");
        CliRun r = CliRun.of("eval", gt.toString(), p[1].toString());
        assertEquals(2, r.code());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().startsWith("trajeval: " + gt + ":3:"), r.err());
        assertFalse(r.err().contains("\tat "));
    }

    @Test
    void unknownOptionValueIsAUsageErrorWithExitCode2() throws IOException {
        Path[] p = offsetPair();
        CliRun r = CliRun.of("eval", p[0].toString(), p[1].toString(), "--align", "se4");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("se4"), r.err());
    }

    @Test
    void missingFileIsRefusedWithExitCode2() {
        CliRun r = CliRun.of("eval", dir.resolve("nope.csv").toString(), dir.resolve("nope2.csv").toString());
        assertEquals(2, r.code());
        assertTrue(r.err().contains("nope"), r.err());
    }

    @Test
    void versionPrintsTheToolVersion() {
        CliRun r = CliRun.of("--version");
        assertEquals(0, r.code());
        assertTrue(r.out().startsWith("trajeval "), r.out());
    }

    @Test
    void evoConventionOnRealTumFilesMatchesEvo() throws IOException {
        // evo_ape tum freiburg1_xyz-groundtruth.txt freiburg1_xyz-rgbdslam.txt (nearest 0.01 s, no
        // alignment): record of ../shared/refdata/evo_reference.json, read here independently
        Path refdata = Paths.get(System.getProperty("trajeval.refdata", "../../shared/refdata"));
        if (!Files.isDirectory(refdata)) {
            // golden data missing: fail unless skipping is asked for knowingly (README, "Golden tests")
            Assumptions.assumeTrue("1".equals(System.getenv("TRAJEVAL_SKIP_REFDATA")), "SKIPPED: TRAJEVAL_SKIP_REFDATA=1");
            org.junit.jupiter.api.Assertions.fail("../shared/refdata is absent; set TRAJEVAL_SKIP_REFDATA=1 to skip");
        }
        var records = new com.fasterxml.jackson.databind.ObjectMapper().readTree(
                refdata.resolve("evo_reference.json").toFile());
        com.fasterxml.jackson.databind.JsonNode expected = null;
        for (var rec : records) {
            var o = rec.get("options");
            if (rec.get("ref").asText().equals("freiburg1_xyz-groundtruth.txt")
                    && rec.get("est").asText().equals("freiburg1_xyz-rgbdslam.txt") && rec.has("ape")
                    && o.get("align").asText().equals("se3") && o.get("pose_relation").asText().equals("trans_part")
                    && o.get("plane").isNull() && o.get("t_max_diff").asDouble() == 0.01
                    && o.get("t_offset").asDouble() == 0.0 && o.get("sync_method").asText().equals("nearest_time")
                    && o.get("delta_unit").asText().equals("frames") && o.get("delta").asInt() == 1
                    && !o.get("all_pairs").asBoolean()) {
                expected = rec;
                break;
            }
        }
        Assumptions.assumeTrue(expected != null, "record not found");
        CliRun r = CliRun.of("eval", refdata.resolve("freiburg1_xyz-groundtruth.txt").toString(),
                refdata.resolve("freiburg1_xyz-rgbdslam.txt").toString(), "--convention", "evo", "--align", "se3",
                "--json");
        assertEquals(0, r.code(), r.err());
        EvaluationReport rep = ReportJson.parseEvaluation(r.out());
        double want = expected.get("ape").get("rmse").asDouble();
        assertEquals(want, rep.ate().transM().rmse(), 1e-9 * want);
        double wantRpe = expected.get("rpe").get("rmse").asDouble();
        assertEquals(wantRpe, rep.rpe().transM().rmse(), 1e-9 * wantRpe);
    }
}
