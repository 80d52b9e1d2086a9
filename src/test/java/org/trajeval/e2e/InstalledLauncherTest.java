package org.trajeval.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/** The installed {@code trajeval} launcher on the real files of ../shared/refdata, as a user runs it. */
class InstalledLauncherTest {

    record Result(int code, String out, String err) {
    }

    private static Result launch(String... args) throws IOException, InterruptedException {
        String launcher = System.getProperty("trajeval.launcher");
        Assumptions.assumeTrue(launcher != null && Files.isExecutable(Paths.get(launcher)),
                "SKIPPED: installed launcher not found (gradle :cli:installDist)");
        List<String> cmd = new ArrayList<>();
        cmd.add(launcher);
        cmd.addAll(List.of(args));
        Path out = Files.createTempFile("trajeval-out", ".txt");
        Path err = Files.createTempFile("trajeval-err", ".txt");
        try {
            Process p = new ProcessBuilder(cmd).redirectOutput(out.toFile()).redirectError(err.toFile()).start();
            assertTrue(p.waitFor(120, TimeUnit.SECONDS), "launcher did not finish");
            return new Result(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8),
                    Files.readString(err, StandardCharsets.UTF_8));
        } finally {
            Files.deleteIfExists(out);
            Files.deleteIfExists(err);
        }
    }

    private static Path refdata() {
        Path dir = Paths.get(System.getProperty("trajeval.refdata", "../shared/refdata"));
        if (!Files.isDirectory(dir)) {
            // golden data missing: fail unless skipping is asked for knowingly (README, "Golden tests")
            Assumptions.assumeTrue("1".equals(System.getenv("TRAJEVAL_SKIP_REFDATA")), "SKIPPED: TRAJEVAL_SKIP_REFDATA=1");
            org.junit.jupiter.api.Assertions.fail("../shared/refdata is absent; set TRAJEVAL_SKIP_REFDATA=1 to skip");
        }
        return dir;
    }

    @Test
    void evalOnFr2DeskMatchesEvoAndPrintsNothingOnStderr() throws Exception {
        Path d = refdata();
        Result r = launch("eval", d.resolve("fr2_desk_groundtruth.txt").toString(),
                d.resolve("fr2_desk_ORB.txt").toString(), "--convention", "evo", "--json");
        assertEquals(0, r.code(), r.err());
        assertEquals("", r.err(), "no JVM banner or warning on stderr");
        JsonNode rep = new ObjectMapper().readTree(r.out());
        // evo_ape tum fr2_desk_groundtruth.txt fr2_desk_ORB.txt (no alignment, nearest 0.01 s):
        // record 0 of ../shared/refdata/evo_reference.json: rmse 3.17399354190223 m over 2174 poses
        assertEquals(2174, rep.at("/association/matched").asInt());
        assertEquals(3.17399354190223, rep.at("/ate/trans_m/rmse").asDouble(), 1e-9 * 3.17399354190223);
        assertEquals(20957, rep.at("/inputs/reference/poses").asInt());
    }

    @Test
    void kittiConventionReportsDriftOnKitti00() throws Exception {
        Path d = refdata();
        Result r = launch("eval", d.resolve("KITTI_00_gt.txt").toString(), d.resolve("KITTI_00_ORB.txt").toString(),
                "--convention", "kitti", "--json");
        assertEquals(0, r.code(), r.err());
        JsonNode rep = new ObjectMapper().readTree(r.out());
        assertEquals(4541, rep.at("/association/matched").asInt());
        assertTrue(rep.at("/drift/segments").asInt() > 0);
        assertTrue(rep.at("/drift/trans_pct").asDouble() > 0);
    }

    @Test
    void duplicateStampsAreRefusedWithExitCode2AndOneLine() throws Exception {
        Path d = refdata();
        Result r = launch("eval", d.resolve("fr2_desk_groundtruth.txt").toString(),
                d.resolve("fr2_desk_ORB.txt").toString());
        assertEquals(2, r.code());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().contains("fr2_desk_groundtruth.txt:10863:"), r.err());
    }
}
