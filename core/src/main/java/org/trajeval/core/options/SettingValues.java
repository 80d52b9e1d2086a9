package org.trajeval.core.options;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Checked evaluation settings: the values a front end was given, each converted by its
 * {@link Setting}, with how it was named (for later refusals). Immutable. Settings not given
 * keep the default of the convention; {@link SettingsResolver} turns them into options.
 */
public final class SettingValues {
    /** No setting given: every default. */
    public static final SettingValues DEFAULTS = new SettingValues(null, new EnumMap<>(Setting.class),
            new EnumMap<>(Setting.class));

    private final String source;
    private final Map<Setting, Object> values;
    private final Map<Setting, String> where;

    private SettingValues(String source, EnumMap<Setting, Object> values, EnumMap<Setting, String> where) {
        this.source = source;
        this.values = Collections.unmodifiableMap(values);
        this.where = Collections.unmodifiableMap(where);
    }

    /**
     * Checks the given settings strictly: unknown keys, a key given twice, a value outside its
     * type or range and settings that exclude each other are refused.
     *
     * @param given the settings as written
     * @param source the file or event they came from, or {@code null} (command line)
     * @throws InputException naming the setting, what was expected and what was found
     */
    public static SettingValues of(List<SettingText> given, String source) {
        return DEFAULTS.with(given, source);
    }

    /**
     * @return these settings with {@code more} added (a key already set here is overridden: a
     *     suite's sequence or method entry refines the suite's {@code metrics})
     * @throws InputException as {@link #of}
     */
    public SettingValues with(List<SettingText> more, String moreSource) {
        EnumMap<Setting, Object> v = new EnumMap<>(Setting.class);
        EnumMap<Setting, String> w = new EnumMap<>(Setting.class);
        v.putAll(values);
        w.putAll(where);
        EnumMap<Setting, String> seen = new EnumMap<>(Setting.class);
        for (SettingText t : more) {
            Setting s = Setting.fromKey(t.key());
            if (s == null) {
                throw new InputException(moreSource, 0, t.where(), InputProblem.INVALID_CONFIGURATION,
                        "'" + t.where() + "': unknown setting; expected one of " + Setting.knownKeys(), t.key());
            }
            if (seen.containsKey(s)) {
                throw new InputException(moreSource, 0, t.where(), InputProblem.INVALID_CONFIGURATION,
                        "'" + t.where() + "': " + s.key() + " is already given as '" + seen.get(s) + "'", t.text());
            }
            seen.put(s, t.where());
            v.put(s, s.parse(t.text(), moreSource, t.where()));
            w.put(s, t.where());
        }
        SettingValues out = new SettingValues(moreSource != null ? moreSource : source, v, w);
        // everything but the data kind is known now: resolve once so inconsistencies surface at intake
        SettingsResolver.evaluationOptions(out, DataKind.SPATIAL);
        return out;
    }

    /** @return whether the setting was given */
    public boolean has(Setting s) {
        return values.containsKey(s);
    }

    /** @return the checked value (see {@link Setting#parse}), or {@code null} when not given */
    public Object get(Setting s) {
        return values.get(s);
    }

    /** @return how the setting was named where it was given (for refusals), or its key */
    public String where(Setting s) {
        return where.getOrDefault(s, s.key());
    }

    /** @return the file or event the settings came from, or {@code null} */
    public String source() {
        return source;
    }

    /** @return the given settings as {@code key=value} pairs in table order, ';'-separated (stable) */
    public String canonical() {
        List<String> parts = new ArrayList<>();
        for (Map.Entry<Setting, Object> e : values.entrySet()) {
            parts.add(e.getKey().key() + "=" + text(e.getValue()));
        }
        return String.join(";", parts);
    }

    /** @return the given settings as text in table order (key to canonical value) */
    public Map<String, String> asText() {
        Map<String, String> out = new java.util.LinkedHashMap<>();
        for (Map.Entry<Setting, Object> e : values.entrySet()) {
            out.put(e.getKey().key(), text(e.getValue()));
        }
        return out;
    }

    private static String text(Object v) {
        if (v instanceof double[] d) {
            StringBuilder sb = new StringBuilder();
            for (int i = 0; i < d.length; i++) {
                sb.append(i == 0 ? "" : ",").append(d[i]);
            }
            return sb.toString();
        }
        if (v instanceof String[] s) {
            return String.join(",", Arrays.asList(s));
        }
        return String.valueOf(v);
    }

    @Override
    public String toString() {
        return "SettingValues{" + canonical() + "}";
    }
}
