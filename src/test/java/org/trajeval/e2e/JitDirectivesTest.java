package org.trajeval.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The compiler directives the installed launchers pass (gradle/jit-directives.json, shipped as
 * lib/jit-directives.json; docs/readme/startup.md): trajeval-pipeline always and trajeval for
 * {@code eval --batch} hand the JVM the shipped file, which is the source tree's; a JVM accepts it (a
 * bad or missing file would stop the JVM at start); the JVM's note about it goes to stderr, not into
 * stdout; a single eval runs without it; TRAJEVAL_JIT_DIRECTIVES=off leaves it out.
 */
class JitDirectivesTest {
    private static final Pattern FLAG = Pattern.compile("\\bCompilerDirectivesFile\\s+=\\s+(\\S*)");
    private static final Pattern TO_STDERR = Pattern.compile("\\bDisplayVMOutputToStderr\\s+=\\s+(\\S+)");
    private static final String ADDED = "2 compiler directives added";

    @TempDir
    Path tmp;

    private record Result(int code, String out, String err) {
    }

    private static Path installed(String property) {
        String l = System.getProperty(property);
        assertTrue(l != null && Files.isExecutable(Path.of(l)), "installed launcher missing: " + l);
        return Path.of(l);
    }

    private Result run(Map<String, String> env, String... cmd) throws IOException, InterruptedException {
        Path out = Files.createTempFile(tmp, "out", ".txt");
        Path err = Files.createTempFile(tmp, "err", ".txt");
        ProcessBuilder pb = new ProcessBuilder(cmd).redirectOutput(out.toFile()).redirectError(err.toFile());
        pb.environment().remove("JAVA_OPTS");
        pb.environment().remove("TRAJEVAL_PIPELINE_OPTS");
        pb.environment().remove("TRAJEVAL_OPTS");
        pb.environment().remove("TRAJEVAL_C1_MAX_BYTES");
        pb.environment().remove("TRAJEVAL_JIT_DIRECTIVES");
        pb.environment().putAll(env);
        Process p = pb.start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "did not finish: " + String.join(" ", cmd));
        return new Result(p.exitValue(), Files.readString(out, StandardCharsets.UTF_8),
                Files.readString(err, StandardCharsets.UTF_8));
    }

    /** An empty drain with the JVM's final flags printed (they go where the JVM's output goes). */
    private Result emptyDrain(Map<String, String> env) throws Exception {
        Path root = Files.createTempDirectory(tmp, "root");
        Files.createDirectories(root.resolve("incoming"));
        Map<String, String> e = new java.util.HashMap<>(env);
        e.put("TRAJEVAL_PIPELINE_OPTS", "-XX:+PrintFlagsFinal");
        Result r = run(e, installed("trajeval.pipelineLauncher").toString(), "watch", "--root", root.toString(),
                "--drain");
        assertEquals(0, r.code(), r.err());
        return r;
    }

    private static Path shipped() {
        return shipped("trajeval.pipelineLauncher");
    }

    private static Path shipped(String launcherProperty) {
        return installed(launcherProperty).getParent().resolveSibling("lib").resolve("jit-directives.json");
    }

    /** trajeval eval ARGS with the JVM's final flags printed. */
    private Result cliEval(String... args) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(installed("trajeval.launcher").toString(), "eval"));
        cmd.addAll(List.of(args));
        Result r = run(Map.of("TRAJEVAL_OPTS", "-XX:+PrintFlagsFinal"), cmd.toArray(new String[0]));
        assertEquals(0, r.code(), r.err());
        return r;
    }

    /** A small 3D TUM pair (the estimate 0.5 m off along x) and a batch file naming it. */
    private Path[] smallPair() throws IOException {
        StringBuilder ref = new StringBuilder();
        StringBuilder est = new StringBuilder();
        for (int i = 0; i < 200; i++) {
            ref.append(String.format(Locale.ROOT, "%.2f %.3f %.3f 0 0 0 0 1%n", 0.1 * i, 0.2 * i, Math.sin(0.05 * i)));
            est.append(String.format(Locale.ROOT, "%.2f %.3f %.3f 0 0 0 0 1%n", 0.1 * i, 0.2 * i + 0.5,
                    Math.sin(0.05 * i)));
        }
        Path r = Files.writeString(tmp.resolve("ref.tum"), ref);
        Path e = Files.writeString(tmp.resolve("est.tum"), est);
        Path pairs = Files.writeString(tmp.resolve("pairs.csv"), "ref,est\n" + r + "," + e + "\n");
        return new Path[] {r, e, pairs};
    }

    @Test
    void pipelineLauncherPassesTheShippedFileAndKeepsStdoutForTheSummary() throws Exception {
        Result r = emptyDrain(Map.of());
        Matcher m = FLAG.matcher(r.err());
        assertTrue(m.find(), r.err());
        assertEquals(shipped().toRealPath(), Path.of(m.group(1)).toRealPath());
        assertTrue(r.err().contains(ADDED), r.err());
        assertFalse(r.out().contains("compiler directives"), r.out());
        assertTrue(r.out().contains("reported=0 "), r.out());
    }

    @Test
    void cliPassesTheShippedFileToBatchesOnly() throws Exception {
        Path[] p = smallPair();
        Result batch = cliEval("--batch", p[2].toString(), "--reports", tmp.resolve("reports").toString());
        Matcher m = FLAG.matcher(batch.err());
        assertTrue(m.find(), batch.err());
        assertEquals(shipped("trajeval.launcher").toRealPath(), Path.of(m.group(1)).toRealPath());
        assertTrue(batch.err().contains(ADDED), batch.err());
        assertFalse(batch.out().contains("compiler directives"), batch.out());
        assertEquals(Files.readString(shipped()), Files.readString(shipped("trajeval.launcher")));

        Result single = cliEval(p[0].toString(), p[1].toString(), "--json");
        Matcher s = TO_STDERR.matcher(single.out());
        assertTrue(s.find(), single.out());
        assertEquals("false", s.group(1));
        assertFalse(single.out().contains("compiler directives") || single.err().contains("compiler directives"),
                single.err());
    }

    @Test
    void shippedFileIsTheSourceTreesAndAJvmAcceptsIt() throws Exception {
        Path source = Path.of(System.getProperty("trajeval.jitDirectives"));
        assertEquals(Files.readString(source), Files.readString(shipped()));
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        Result r = run(Map.of(), java, "-XX:+UnlockDiagnosticVMOptions", "-XX:CompilerDirectivesFile=" + shipped(),
                "-version");
        assertEquals(0, r.code(), r.out() + r.err());
        assertEquals(ADDED, r.out().strip());
    }

    @Test
    void aJvmRefusesABadFileWhichIsWhyTheLauncherChecksForIt() throws Exception {
        Path bad = Files.writeString(tmp.resolve("bad.json"), "[{ match: \"*.*\", c2: { Exclude: tru } }]\n");
        String java = Path.of(System.getProperty("java.home"), "bin", "java").toString();
        assertEquals(1, run(Map.of(), java, "-XX:+UnlockDiagnosticVMOptions", "-XX:CompilerDirectivesFile=" + bad,
                "-version").code());
    }

    @Test
    void offInTheEnvironmentLeavesTheDirectivesOut() throws Exception {
        Result r = emptyDrain(Map.of("TRAJEVAL_JIT_DIRECTIVES", "off"));
        // the JVM's output stays on stdout, and no directives were added
        Matcher m = TO_STDERR.matcher(r.out());
        assertTrue(m.find(), r.out());
        assertEquals("false", m.group(1));
        assertFalse(r.out().contains("compiler directives") || r.err().contains("compiler directives"), r.err());
    }
}
