package org.trajeval.core;

/**
 * Makes text copied from an input safe to print on a terminal or in a one-line log record: every
 * control character (C0, DEL, C1), line or paragraph separator and bidirectional override is
 * replaced by a visible escape, so a file name or field cannot move the cursor, retitle the
 * terminal, clear the screen or start a forged log line.
 *
 * <p>Example: {@code "a\u001b]0;PWNED\u0007\nb"} becomes {@code a\e]0;PWNED\a\nb} (backslash
 * escapes as C writes them; others as {@code \xNN} or {@code \u202E}). Printable text, including
 * non-ASCII letters, is unchanged, and escaping twice changes nothing more.
 */
public final class InputText {
    private InputText() {
    }

    /** @return {@code text} with every non-printable character escaped; {@code null} stays {@code null} */
    public static String escape(String text) {
        if (text == null) {
            return null;
        }
        int i = 0;
        while (i < text.length() && !needsEscape(text.charAt(i))) {
            i++;
        }
        if (i == text.length()) {
            return text;
        }
        StringBuilder sb = new StringBuilder(text.length() + 16).append(text, 0, i);
        for (; i < text.length(); i++) {
            char c = text.charAt(i);
            if (!needsEscape(c)) {
                sb.append(c);
                continue;
            }
            switch (c) {
                case '\n' -> sb.append("\\n");
                case '\r' -> sb.append("\\r");
                case '\t' -> sb.append("\\t");
                case 0x1b -> sb.append("\\e");
                case 0x07 -> sb.append("\\a");
                case 0x08 -> sb.append("\\b");
                case 0x00 -> sb.append("\\0");
                default -> sb.append(c < 0x100 ? String.format("\\x%02X", (int) c) : String.format("\\u%04X", (int) c));
            }
        }
        return sb.toString();
    }

    /** @return true for C0/C1 controls, DEL, U+2028/U+2029 and the bidirectional controls */
    static boolean needsEscape(char c) {
        return c < 0x20 || (c >= 0x7f && c < 0xa0) || c == '\u2028' || c == '\u2029'
                || (c >= '\u202a' && c <= '\u202e') || (c >= '\u2066' && c <= '\u2069') || c == '\u200e'
                || c == '\u200f' || c == '\u061c';
    }
}
