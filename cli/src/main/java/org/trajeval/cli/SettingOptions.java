package org.trajeval.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.trajeval.core.options.Setting;
import org.trajeval.core.options.SettingKind;
import org.trajeval.core.options.SettingText;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Model.OptionSpec;
import picocli.CommandLine.ParseResult;

/**
 * The command-line face of the core's settings table: one option per {@link Setting} (its flag,
 * label, help), added to a command at start-up, and the given ones read back as text for the
 * core's resolver. Values are checked by the core, so the command line refuses exactly what a
 * manifest, a run.yaml or a Kafka event refuses.
 */
final class SettingOptions {
    private SettingOptions() {
    }

    /** Adds every setting's option (and its switches) to {@code spec}. */
    static void addTo(CommandSpec spec) {
        for (Setting s : Setting.values()) {
            // picocli reads a description as a format string: the help's plain "%" is written "%%"
            OptionSpec.Builder b = OptionSpec.builder(s.flag()).description(s.help().replace("%", "%%"));
            if (s.kind() == SettingKind.SWITCH) {
                b.type(boolean.class).arity("0");
            } else {
                b.type(String.class).paramLabel(s.allowed());
            }
            spec.addOption(b.build());
            for (Map.Entry<String, String> sw : s.switches().entrySet()) {
                spec.addOption(OptionSpec.builder(sw.getKey()).type(boolean.class).arity("0")
                        .description("Short for " + s.flag() + " " + sw.getValue() + ".").build());
            }
        }
    }

    /** @return the settings given on the command line, named by their flags */
    static List<SettingText> given(ParseResult parsed) {
        List<SettingText> out = new ArrayList<>();
        for (Setting s : Setting.values()) {
            if (parsed.hasMatchedOption(s.flag())) {
                Object v = parsed.matchedOptionValue(s.flag(), null);
                out.add(new SettingText(s.key(), s.kind() == SettingKind.SWITCH ? "true" : String.valueOf(v), s.flag()));
            }
            for (Map.Entry<String, String> sw : s.switches().entrySet()) {
                if (parsed.hasMatchedOption(sw.getKey())) {
                    out.add(new SettingText(s.key(), sw.getValue(), sw.getKey()));
                }
            }
        }
        return out;
    }
}
