package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.trajeval.core.options.Setting;

class SettingOptionsTest {
    @Test
    void everySettingsHelpIsPrintedAsWrittenWithoutPicocliWarnings() {
        // picocli reads a description as a format string: a plain "%" (Setting's "50 % of the
        // reference path") made it warn on standard error and print the text unformatted
        PrintStream original = System.err;
        ByteArrayOutputStream warnings = new ByteArrayOutputStream();
        String usage;
        try {
            System.setErr(new PrintStream(warnings, true, StandardCharsets.UTF_8));
            usage = TrajevalCommand.newCommandLine().getSubcommands().get("eval").getUsageMessage();
        } finally {
            System.setErr(original);
        }
        assertEquals("", warnings.toString(StandardCharsets.UTF_8));
        String flowing = usage.replaceAll("\\s+", " ");
        for (Setting s : Setting.values()) {
            assertTrue(flowing.contains(s.help().replaceAll("\\s+", " ")), s.flag() + "'s help as written");
        }
        assertTrue(flowing.contains("default 10,20,30,40,50 % of the reference path"));
    }
}
