package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import picocli.CommandLine;

/** Bad input exits 2 naming what was wrong; anything else is our bug: exit 1, "internal error", --verbose. */
class ErrorModelTest {

    private static int handle(Exception e, StringWriter err) {
        CommandLine cl = TrajevalCommand.newCommandLine();
        cl.setErr(new PrintWriter(err));
        CommandLine.ParseResult parsed = cl.parseArgs();
        return new TrajevalCommand.ErrorHandler().handleExecutionException(e, cl, parsed);
    }

    @Test
    void anIllegalArgumentFromInsideIsAnInternalErrorNotTheUsersFault() {
        StringWriter err = new StringWriter();
        int code = handle(new IllegalArgumentException("scale must be positive, got -1.0"), err);
        assertEquals(ExitCodes.INTERNAL, code);
        assertTrue(err.toString().startsWith("trajeval: internal error: "), err.toString());
        assertTrue(err.toString().contains("--verbose"), err.toString());
    }

    @Test
    void badInputExitsTwoWithOneLine() {
        StringWriter err = new StringWriter();
        int code = handle(new InputException("est.csv", 3, "x", InputProblem.NOT_A_NUMBER,
                "column 'x' must be a number (m)", "oops"), err);
        assertEquals(ExitCodes.BAD_INPUT, code);
        assertEquals("trajeval: est.csv:3: column 'x' must be a number (m), found \"oops\"", err.toString().trim());
        assertFalse(err.toString().contains("internal"));
    }

    @Test
    void badSettingValuesOnTheCommandLineExitTwoNamingTheFlag() {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        CommandLine cl = TrajevalCommand.newCommandLine();
        cl.setOut(new PrintWriter(out));
        cl.setErr(new PrintWriter(err));
        int code = cl.execute("eval", "a.csv", "b.csv", "--max-diff", "-1");
        assertEquals(ExitCodes.BAD_INPUT, code);
        assertEquals("trajeval: --max-diff must be a number > 0 (s), found \"-1\"", err.toString().trim());
    }
}
