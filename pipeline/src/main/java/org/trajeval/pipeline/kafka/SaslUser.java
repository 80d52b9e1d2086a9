package org.trajeval.pipeline.kafka;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** Reads the user name (never the password) out of a {@code sasl.jaas.config} value, for messages. */
final class SaslUser {
    private static final Pattern USERNAME = Pattern.compile("\\busername\\s*=\\s*\"([^\"]*)\"");

    private SaslUser() {
    }

    /** @return the user name, or null when none is set */
    static String of(String jaasConfig) {
        if (jaasConfig == null) {
            return null;
        }
        Matcher m = USERNAME.matcher(jaasConfig);
        return m.find() ? m.group(1) : null;
    }
}
