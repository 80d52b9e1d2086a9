package org.trajeval.pipeline.bundle;

import com.fasterxml.jackson.databind.node.IntNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.LongNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import com.fasterxml.jackson.databind.node.TextNode;
import java.util.Locale;
import java.util.Set;

/**
 * The plainest run.yaml, read without a YAML parser: every line {@code key: value}, the key lower-case
 * letters, digits and '_' (at most 64 of them), the value either a word (a letter, then letters, digits, '_', '.', '-', '/';
 * not a YAML boolean or null such as {@code yes}, {@code off}, {@code null}) or a whole number without
 * sign, leading zero or separator (at most 18 digits). For such a file the tree is the one the YAML
 * mapper gives (text, int or long nodes, keys in file order); anything else (comments, quotes, nested
 * mappings, blank lines, a repeated key, ...) returns null and is read by the YAML mapper, which also
 * gives every refusal its message. A bundle's run.yaml is read once per run: this skips a YAML parse
 * and the compilation of the parser's code in the service's JIT.
 */
final class PlainRunYaml {
    /** Words the YAML mapper reads as a boolean or null (compared in lower case). */
    private static final Set<String> NOT_TEXT = Set.of("true", "false", "yes", "no", "y", "n", "on", "off", "null");
    /** Digits of the longest number read here (a long, as the YAML mapper reads up to 18 digits). */
    private static final int MAX_DIGITS = 18;
    /**
     * Longest key read here (characters). YAML takes a key without '?' only up to 1024 characters: past that
     * the YAML mapper reads the line as one text or refuses the file, so a long key is left to it (the
     * longest key a run.yaml knows has 16).
     */
    private static final int MAX_KEY_CHARS = 64;

    private PlainRunYaml() {
    }

    /** @return the mapping in {@code text}, or null when the text is not of the plain form above */
    static ObjectNode read(String text) {
        ObjectNode root = JsonNodeFactory.instance.objectNode();
        int n = text.length();
        int at = 0;
        while (at < n) {
            int end = text.indexOf('\n', at);
            if (end < 0) {
                end = n;
            }
            int colon = text.indexOf(':', at);
            if (colon <= at || colon + 2 >= end || text.charAt(colon + 1) != ' ' || !isKey(text, at, colon)) {
                return null;
            }
            String key = text.substring(at, colon);
            String value = text.substring(colon + 2, end);
            if (root.has(key)) {
                return null;
            }
            if (isWord(value)) {
                root.set(key, TextNode.valueOf(value));
            } else if (isWholeNumber(value)) {
                long v = Long.parseLong(value);
                root.set(key, v <= Integer.MAX_VALUE ? IntNode.valueOf((int) v) : LongNode.valueOf(v));
            } else {
                return null;
            }
            at = end + 1;
        }
        return root.isEmpty() ? null : root;
    }

    private static boolean isKey(String s, int from, int to) {
        if (to - from > MAX_KEY_CHARS) {
            return false;
        }
        for (int i = from; i < to; i++) {
            char c = s.charAt(i);
            if (!(c >= 'a' && c <= 'z' || c == '_' || i > from && c >= '0' && c <= '9')) {
                return false;
            }
        }
        return true;
    }

    private static boolean isWord(String v) {
        if (!isLetter(v.charAt(0))) {
            return false;
        }
        for (int i = 1; i < v.length(); i++) {
            char c = v.charAt(i);
            if (!(isLetter(c) || c >= '0' && c <= '9' || c == '_' || c == '.' || c == '-' || c == '/')) {
                return false;
            }
        }
        return !NOT_TEXT.contains(v.toLowerCase(Locale.ROOT));
    }

    private static boolean isLetter(char c) {
        return c >= 'a' && c <= 'z' || c >= 'A' && c <= 'Z';
    }

    private static boolean isWholeNumber(String v) {
        if (v.length() > MAX_DIGITS || v.charAt(0) == '0' && v.length() > 1) {
            return false;
        }
        for (int i = 0; i < v.length(); i++) {
            char c = v.charAt(i);
            if (c < '0' || c > '9') {
                return false;
            }
        }
        return true;
    }
}
