package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * The launcher's command line for {@code trajeval eval ...} knows only {@code eval} (picocli
 * models no other subcommand, a start-up cost): it must behave exactly like the whole command.
 * Reference: {@link TrajevalCommand#newCommandLine()} on the same arguments.
 */
class EvalOnlyCommandLineTest {
    @TempDir
    Path dir;

    private static CliRun run(CommandLine cl, String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(err));
        int code = cl.execute(args);
        return new CliRun(code, out.toString(), err.toString());
    }

    private void assertSameAsWholeCommand(String... args) {
        CliRun whole = run(TrajevalCommand.newCommandLine(), args);
        CliRun evalOnly = run(TrajevalCommand.newCommandLine(args), args);
        assertEquals(whole, evalOnly, String.join(" ", args));
    }

    private Path csv(String name, double left) throws IOException {
        StringBuilder b = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i <= 50; i++) {
            b.append(i * 0.1).append(',').append(i * 0.1).append(',').append(left).append(",0\n");
        }
        return Files.write(dir.resolve(name), b.toString().getBytes(StandardCharsets.UTF_8));
    }

    @Test
    void evalCommandLineModelsOnlyEval() {
        CommandLine cl = TrajevalCommand.newCommandLine(new String[] {"eval", "a.csv", "b.csv"});
        assertEquals(java.util.Set.of("eval"), cl.getSubcommands().keySet());
        assertEquals("trajeval eval", cl.getSubcommands().get("eval").getCommandSpec().qualifiedName());
    }

    @Test
    void otherCommandsGetTheWholeCommandLine() {
        for (String[] args : new String[][] {{}, {"--help"}, {"suite", "run"}, {"evaluate"}, {"--version", "eval"}}) {
            assertTrue(TrajevalCommand.newCommandLine(args).getSubcommands().size() > 1, String.join(" ", args));
        }
    }

    @Test
    void reportsHelpVersionAndErrorsAreThoseOfTheWholeCommand() throws IOException {
        String ref = csv("ref.csv", 0).toString();
        String est = csv("est.csv", 0.1).toString();
        assertSameAsWholeCommand("eval", ref, est);
        assertSameAsWholeCommand("eval", ref, est, "--json", "--convention", "lesson", "--association", "interpolate",
                "--align", "se2", "--rpe-delta", "1", "--rpe-unit", "s", "--threads", "1");
        assertSameAsWholeCommand("eval", ref, est, "--json", "--align=none", "--verbose");
        assertSameAsWholeCommand("eval", "--help");
        assertSameAsWholeCommand("eval", "--version");
        assertSameAsWholeCommand("eval");
        assertSameAsWholeCommand("eval", ref);
        assertSameAsWholeCommand("eval", ref, est, "--bogus");
        assertSameAsWholeCommand("eval", ref, est, "--align", "sideways");
        assertSameAsWholeCommand("eval", ref, est, "--threads", "0");
        assertSameAsWholeCommand("eval", ref, est, "--out");
        assertSameAsWholeCommand("eval", ref, dir.resolve("missing.csv").toString());
        assertSameAsWholeCommand("eval", ref, dir.resolve("missing.csv").toString(), "--verbose");
        assertSameAsWholeCommand("eval", "--batch", dir.resolve("pairs.csv").toString());
    }
}
