package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.protocol.DemoBenchmark;
import org.w3c.dom.Document;

/**
 * The gate and the store on the demo suite: alpha replaced by beta must fail, the demo on new data
 * (another data seed, methods of the same quality) must pass; the same through the store.
 */
class GateCommandTest {
    @TempDir
    static Path dir;
    private static Path base;
    private static Path rerun;
    private static Path replaced;
    private static Path db;

    private static Path suite(Path manifest, String name, String version) {
        Path out = dir.resolve(name);
        CliRun r = CliRun.of("suite", manifest.toString(), "--out", out.toString(), "--allow-leakage", "--threads", "2",
                "--resamples", "1000", "--db", db.toString(), "--tag", "software_version=" + version);
        assertEquals(0, r.code(), r.err());
        return out.resolve("report.json");
    }

    @BeforeAll
    static void suites() throws IOException {
        db = dir.resolve("trajeval.db");
        Path m7 = DemoBenchmark.write(dir.resolve("bench7"), 7);
        base = suite(m7, "base", "2.3");
        rerun = suite(DemoBenchmark.write(dir.resolve("bench8"), 8), "rerun", "2.4-rerun");
        // the candidate: method alpha's estimates are beta's files
        Path swapped = m7.resolveSibling("alpha-is-beta.yaml");
        String text = Files.readString(m7);
        String alpha = "{name: alpha, estimates: \"runs/{method}/";
        assertTrue(text.contains(alpha), text);
        Files.writeString(swapped, text.replace(alpha, "{name: alpha, estimates: \"runs/beta/"));
        replaced = suite(swapped, "replaced", "2.4");
    }

    @Test
    void alphaReplacedByBetaFailsTheGateWithExitFive() throws Exception {
        Path md = dir.resolve("gate.md");
        Path junit = dir.resolve("gate.xml");
        CliRun r = CliRun.of("gate", base.toString(), replaced.getParent().toString(), "--markdown", md.toString(), "--junit",
                junit.toString());
        assertEquals(ExitCodes.REGRESSION, r.code(), r.out() + r.err());
        assertTrue(r.out().lines().anyMatch(l -> l.startsWith("alpha") && l.contains("ate_trans_rmse_m")
                && l.endsWith("regression")), r.out());
        assertTrue(r.out().lines().filter(l -> l.startsWith("beta") || l.startsWith("gamma"))
                .noneMatch(l -> l.endsWith("regression")), "beta and gamma are unchanged: " + r.out());
        assertTrue(Files.readString(md).startsWith("### trajeval gate: FAIL"), Files.readString(md));
        Document x = DocumentBuilderFactory.newInstance().newDocumentBuilder().parse(junit.toFile());
        // 3 methods x 2 score metrics, each one aggregate case and 8 sequence cases
        assertEquals("54", x.getDocumentElement().getAttribute("tests"));
        assertTrue(Integer.parseInt(x.getDocumentElement().getAttribute("failures")) >= 2);
    }

    @Test
    void theDemoOnNewDataWithMethodsOfTheSameQualityPasses() {
        CliRun r = CliRun.of("gate", base.toString(), rerun.toString());
        assertEquals(ExitCodes.OK, r.code(), r.out() + r.err());
        assertTrue(r.out().contains("gate: PASS"), r.out());
    }

    @Test
    void theStoreGivesTheSameVerdictsBySoftwareVersion() {
        CliRun fail = CliRun.of("gate", "--db", db.toString(), "--baseline", "software_version=2.3", "--candidate",
                "version=2.4");
        assertEquals(ExitCodes.REGRESSION, fail.code(), fail.out() + fail.err());
        CliRun pass = CliRun.of("gate", "--db", db.toString(), "--baseline", "software_version=2.3", "--candidate",
                "version=2.4-rerun");
        assertEquals(ExitCodes.OK, pass.code(), pass.out() + pass.err());
    }

    @Test
    void trendByVersionFlagsAlphaWhoseLatestVersionRanBetasEstimates() throws IOException {
        Path page = dir.resolve("trend.html");
        CliRun r = CliRun.of("trend", "--db", db.toString(), "--metric", "ate_trans_rmse_m", "--by", "method", "--bucket",
                "version", "--html", page.toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().lines().anyMatch(l -> l.startsWith("alpha") && l.contains("latest") && l.endsWith("WORSE")),
                r.out());
        assertTrue(r.out().lines().filter(l -> l.contains("latest") && !l.startsWith("alpha"))
                .noneMatch(l -> l.endsWith("WORSE")), r.out());
        assertTrue(Files.readString(page).contains("alpha &#8212; WORSE"));
    }

    @Test
    void importingTheReportsAgainChangesNothing() {
        CliRun r = CliRun.of("db", "import", dir.resolve("base").toString(), "--db", db.toString(), "--tag",
                "software_version=2.3");
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("120 result(s), 0 new"), r.out());
    }

    @Test
    void anUnknownMetricIsRefusedWithOneLine() {
        CliRun r = CliRun.of("gate", base.toString(), rerun.toString(), "--max-regression", "ate_rmse=5");
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().contains("--max-regression: expected METRIC=PCT"), r.err());
    }

    @Test
    void aPasswordInTheUrlIsRefused() {
        CliRun r = CliRun.of("db", "info", "--db", "jdbc:postgresql://127.0.0.1:1/x?user=u&password=hunter2");
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        assertTrue(r.err().contains("the URL holds a password"), r.err());
        assertTrue(!r.err().contains("hunter2"), r.err());
    }
}
