package org.trajeval.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
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
 * and for --batch; docs/readme/startup.md); a single eval compiles core's methods sooner.
 */
class LauncherScriptTest {
    private static final Pattern TIER = Pattern.compile("\\bTieredStopAtLevel\\s+=\\s+(\\d+)");
    private static final Pattern COMMAND = Pattern.compile("\\bCompileCommand\\s+\\+?=\\s+(\\S+)");

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

    /**
     * @return the JVM's final flags of this run (stdout, or stderr where the launcher sends the JVM's output
     *     there), whatever the command's exit code (the batch here reports the awkward names as it can)
     */
    private static String flags(Map<String, String> env, String... args) throws Exception {
        Map<String, String> e = new java.util.HashMap<>(env);
        e.put("TRAJEVAL_OPTS", "-XX:+PrintFlagsFinal");
        Result r = launch(e, args);
        return r.out() + r.err();
    }

    /** @return the values of CompileCommand the JVM was given, as PrintFlagsFinal lists them */
    private static List<String> compileCommands(String flags) {
        List<String> found = new ArrayList<>();
        Matcher m = COMMAND.matcher(flags);
        while (m.find()) {
            found.add(m.group(1));
        }
        return found;
    }

    @Test
    void singleEvalsCompileCoreSoonerBatchesAndOtherCommandsDoNot() throws Exception {
        String sooner = "CompileThresholdScaling,org.trajeval.core.*::*,0.1";
        // C1 only (small inputs) and both compilers (inputs above the limit)
        assertTrue(compileCommands(flags(Map.of(), "eval", ref.toString(), est.toString(), "--json")).contains(sooner));
        assertTrue(compileCommands(flags(Map.of("TRAJEVAL_C1_MAX_BYTES", "0"), "eval", ref.toString(), est.toString(),
                "--json")).contains(sooner));
        Path pairs = Files.writeString(tmp.resolve("pairs-sooner.csv"), "ref,est\n\"" + ref + "\",\"" + est + "\"\n");
        List<String> batch = compileCommands(flags(Map.of(), "eval", "--batch", pairs.toString(), "--reports",
                tmp.resolve("out-sooner").toString()));
        assertTrue(batch.contains("quiet"), batch.toString());
        assertFalse(batch.contains(sooner), batch.toString());
        assertFalse(compileCommands(flags(Map.of(), "--version")).contains(sooner));
    }

    @Test
    void aJvmReadsTheScalingAsCoresPackagesAtATenth() throws Exception {
        String java = Paths.get(System.getProperty("java.home"), "bin", "java").toString();
        Process p = new ProcessBuilder(java, "-XX:CompileCommand=CompileThresholdScaling,org.trajeval.core.*::*,0.1",
                "-version").redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, p.waitFor(), out);
        // the JVM echoes the command it registered (the launcher's "quiet" silences this)
        assertTrue(out.contains("CompileCommand: CompileThresholdScaling org/trajeval/core/*.* double"
                + " CompileThresholdScaling = 0.100000"), out);
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
