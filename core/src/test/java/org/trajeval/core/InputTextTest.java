package org.trajeval.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import org.junit.jupiter.api.Test;

class InputTextTest {
    @Test
    void terminalEscapesNewlinesAndBidiOverridesBecomeVisibleEscapes() {
        assertEquals("a\\e]0;PWNED\\a\\e[2J\\nb\\r\\t\\0\\x7F\\x9B\\u202E",
                InputText.escape("a\u001b]0;PWNED\u0007\u001b[2J\nb\r\t\u0000\u007f\u009b\u202e"));
    }

    @Test
    void printableTextIncludingNonAsciiLettersIsUnchangedAndEscapingTwiceChangesNothing() {
        String s = "runs/Zürich 東京/gt.csv \\ \"quoted\"";
        assertSame(s, InputText.escape(s));
        String once = InputText.escape("x\u001by\n");
        assertEquals(once, InputText.escape(once));
    }

    @Test
    void anInputExceptionMessageIsOneEscapedLineButItsFieldsKeepTheTextAsRead() {
        InputException e = new InputException("f\n.csv", 2, "x", InputProblem.NOT_A_NUMBER, "column 'x' must be a number",
                "\u001b[2J");
        assertEquals("f\\n.csv:2: column 'x' must be a number, found \"\\e[2J\"", e.getMessage());
        assertEquals("\u001b[2J", e.found());
    }
}
