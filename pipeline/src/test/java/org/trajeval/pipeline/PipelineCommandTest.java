package org.trajeval.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

class PipelineCommandTest {
    @TempDir
    Path root;

    private int run(StringWriter out, String... args) {
        CommandLine cl = PipelineCommand.newCommandLine(c -> new StandInScorer(), Map.of());
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(out));
        return cl.execute(args);
    }

    @Test
    void drainExitsZeroWhenAllSucceedAndFourWhenSomeFailed() throws Exception {
        Path in = root.resolve("incoming");
        Fixtures.pair(in, "good", 30, 1);
        Fixtures.marker(in, "good");
        StringWriter out = new StringWriter();
        assertEquals(0, run(out, "watch", "--root", root.toString(), "--drain"));
        assertTrue(out.toString().contains("reported=1 duplicates=0 failed=0"), out.toString());
        Fixtures.write(in.resolve("bad.gt.csv"), "t,x,y,yaw\n0,0,0,0\n1,x,0,0\n");
        Fixtures.pair(in, "bad2", 30, 2);
        Files.delete(in.resolve("bad2.est.csv"));
        Fixtures.marker(in, "bad");
        assertEquals(4, run(new StringWriter(), "watch", "--root", root.toString(), "--drain"));
    }

    @Test
    void badConfigurationExitsTwoWithOneLine() {
        StringWriter out = new StringWriter();
        assertEquals(2, run(out, "watch", "--root", root.toString(), "--drain", "--set", "nope=1"));
        assertEquals("trajeval-pipeline: --set nope: unknown configuration key 'nope', found \"nope\"",
                out.toString().trim());
    }
}
