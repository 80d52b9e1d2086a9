package org.trajeval.core.options;

import java.util.Objects;

/**
 * One setting as a front end received it, before checking.
 *
 * @param key the setting's key ({@code max_diff_s}); unknown keys are refused when checked
 * @param text the value as written (a flag's argument, a YAML or JSON scalar; lists joined by commas)
 * @param where how to name it in a refusal: the flag ({@code --max-diff}) or the key path in the
 *     file ({@code metrics.rpe.delta})
 */
public record SettingText(String key, String text, String where) {
    /** @throws NullPointerException on a missing key or where */
    public SettingText {
        Objects.requireNonNull(key, "key");
        Objects.requireNonNull(where, "where");
    }
}
