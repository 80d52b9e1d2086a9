package org.trajeval.spark;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.options.Setting;
import org.trajeval.core.options.SettingKind;
import org.trajeval.core.options.SettingText;

/**
 * The evaluation options of {@code trajeval eval} on the job's command line, read through the
 * core's settings table (each {@link Setting}'s flag and switches): {@code --align se3},
 * {@code --align=se3}, {@code --planar}, {@code --evo}. Values are not checked here: the core
 * checks them as for every front end.
 */
final class EvalFlags {
    private EvalFlags() {
    }

    /**
     * @param args what is left of the command line after the job's own options
     * @return the settings, named by their flags
     * @throws InputException (INVALID_OPTION) on an argument that is no evaluation option, or a flag without its value
     */
    static List<SettingText> parse(List<String> args) {
        List<SettingText> out = new ArrayList<>();
        for (int i = 0; i < args.size(); i++) {
            String arg = args.get(i);
            int eq = arg.indexOf('=');
            String flag = arg.startsWith("--") && eq > 0 ? arg.substring(0, eq) : arg;
            String inline = arg.startsWith("--") && eq > 0 ? arg.substring(eq + 1) : null;
            SettingText t = null;
            for (Setting s : Setting.values()) {
                if (s.flag().equals(flag)) {
                    String value;
                    if (s.kind() == SettingKind.SWITCH) {
                        value = inline != null ? inline : "true";
                    } else if (inline != null) {
                        value = inline;
                    } else if (i + 1 < args.size()) {
                        value = args.get(++i);
                    } else {
                        throw new InputException(null, 0, flag, InputProblem.INVALID_OPTION, "option '" + flag
                                + "' needs a value (" + s.allowed() + ")", null);
                    }
                    t = new SettingText(s.key(), value, flag);
                }
                for (Map.Entry<String, String> sw : s.switches().entrySet()) {
                    if (sw.getKey().equals(arg)) {
                        t = new SettingText(s.key(), sw.getValue(), arg);
                    }
                }
            }
            if (t == null) {
                throw new InputException(null, 0, null, InputProblem.INVALID_OPTION, "unknown option or argument;"
                        + " expected the job's options or an option of trajeval eval (see trajeval-spark score --help)",
                        arg);
            }
            out.add(t);
        }
        return out;
    }
}
