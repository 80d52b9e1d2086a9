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
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The installed start script: it hands every argument to the command unchanged, and picks the JIT
 * by the size of an eval's input files (C1 only up to TRAJEVAL_C1_MAX_BYTES, both compilers above
 * and for --batch; docs/readme/startup.md).
 */
class LauncherScriptTest {
    private static final Pattern TIER = Pattern.compile("\\bTieredStopAtLevel\\s+=\\s+(\\d+)");

    @TempDir
    static Path tmp;
    private static Path launcher;
    private static Path ref;
    private static Path est;

    record Result(int code, String out, String err) {
    }

    @BeforeAll
    static void installedLauncherAndASmallPairWithAwkwardNames() throws IOException {
        String l = System.getProperty("trajeval.launcher");
        Assumptions.assumeTrue(l != null && Files.isExecutable(Paths.get(l)),
                "SKIPPED: installed launcher not found (gradle :cli:installDist)");
        launcher = Paths.get(l);
        StringBuilder r = new StringBuilder("t,x,y,yaw\n");
        StringBuilder e = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i < 200; i++) {
            r.append(String.format(Locale.ROOT, "%.1f,%.3f,%.3f,0%n", 0.1 * i, 0.2 * i, Math.sin(0.05 * i)));
            e.append(String.format(Locale.ROOT, "%.1f,%.3f,%.3f,0%n", 0.1 * i, 0.2 * i + 0.5, Math.sin(0.05 * i)));
        }
        // what a shell would expand or split if the script quoted an argument wrongly
        Path dir = Files.createDirectories(tmp.resolve("a folder"));
        ref = Files.writeString(dir.resolve("ref $HOME 'q' \"d\" *.csv"), r);
        est = Files.writeString(dir.resolve("est\\n `x` ;.csv"), e);
    }

    private static Result launch(Map<String, String> env, String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>();
        cmd.add(launcher.toString());
        cmd.addAll(List.of(args));
        Path out = Files.createTempFile(tmp, "out", ".txt");
        Path err = Files.createTempFile(tmp, "err", ".txt");
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(tmp.toFile())
                .redirectOutput(out.toFile()).redirectError(err.toFile());
        pb.environment().remove("JAVA_OPTS");
        pb.environment().remove("TRAJEVAL_OPTS");
        pb.environment().remove("TRAJEVAL_C1_MAX_BYTES");
        pb.environment().putAll(env);
        Process p = pb.start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "launcher did not finish");
        return new Result(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8),
                Files.readString(err, StandardCharsets.UTF_8));
    }

    /** @return the TieredStopAtLevel the JVM of this run had (4: C1 and C2; 1: C1 only) */
    private static int tier(Map<String, String> env, String... args) throws Exception {
        Map<String, String> e = new java.util.HashMap<>(env);
        e.put("TRAJEVAL_OPTS", "-XX:+PrintFlagsFinal");
        Result r = launch(e, args);
        // --batch runs with -XX:+DisplayVMOutputToStderr (JitDirectivesTest): the flags are on stderr
        Matcher m = TIER.matcher(r.out() + r.err());
        assertTrue(m.find(), r.err());
        return Integer.parseInt(m.group(1));
    }

    @Test
    void argumentsReachTheCommandUnchanged() throws Exception {
        Result r = launch(Map.of(), "eval", ref.toString(), est.toString(), "--align", "none", "--json");
        assertEquals(0, r.code(), r.err());
        JsonNode rep = new ObjectMapper().readTree(r.out());
        assertEquals(ref.toString(), rep.at("/inputs/reference/path").asText());
        assertEquals(est.toString(), rep.at("/inputs/estimate/path").asText());
        // 0.5 m along x everywhere, no alignment: ATE 0.5 m by hand
        assertEquals(0.5, rep.at("/ate/trans_m/rmse").asDouble(), 1e-9);
    }

    @Test
    void smallInputsRunWithC1Only() throws Exception {
        assertEquals(1, tier(Map.of(), "eval", ref.toString(), est.toString(), "--json"));
    }

    @Test
    void inputsAboveTheLimitAndBatchesGetBothCompilers() throws Exception {
        long bytes = Files.size(ref) + Files.size(est);
        assertEquals(1, tier(Map.of("TRAJEVAL_C1_MAX_BYTES", Long.toString(bytes)), "eval", ref.toString(),
                est.toString(), "--json"));
        assertEquals(4, tier(Map.of("TRAJEVAL_C1_MAX_BYTES", Long.toString(bytes - 1)), "eval", ref.toString(),
                est.toString(), "--json"));
        assertEquals(4, tier(Map.of("TRAJEVAL_C1_MAX_BYTES", "0"), "eval", ref.toString(), est.toString(), "--json"));
        Path pairs = Files.writeString(tmp.resolve("pairs.csv"), "ref,est\n\"" + ref + "\",\"" + est + "\"\n");
        assertEquals(4, tier(Map.of(), "eval", "--batch", pairs.toString(), "--reports", tmp.resolve("out").toString()));
        assertEquals(4, tier(Map.of(), "--version"));
    }

    @Test
    void aLimitThatIsNotAWholeNumberIsRefusedInOneLine() throws Exception {
        Result r = launch(Map.of("TRAJEVAL_C1_MAX_BYTES", "48M"), "eval", ref.toString(), est.toString(), "--json");
        assertEquals(2, r.code(), r.err());
        assertEquals("trajeval: environment variable TRAJEVAL_C1_MAX_BYTES must be a whole number of bytes"
                + " (0: never C1 only), found \"48M\"\n", r.err());
        assertEquals("", r.out());
    }
}
