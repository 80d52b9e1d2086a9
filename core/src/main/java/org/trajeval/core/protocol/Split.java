package org.trajeval.core.protocol;

import java.util.Locale;

/** The split a sequence belongs to. */
public enum Split {
    /** Training data: methods may be tuned on it. */
    TRAIN,
    /** Validation data: for model selection. */
    VAL,
    /** Test data: reported, never tuned on. */
    TEST;

    /** @return the name as written in manifests and reports: train, val, test */
    public String key() {
        return name().toLowerCase(Locale.ROOT);
    }

    /** @return the split named {@code key} (train, val, test), or {@code null} */
    public static Split fromKey(String key) {
        for (Split s : values()) {
            if (s.key().equals(key)) {
                return s;
            }
        }
        return null;
    }
}
