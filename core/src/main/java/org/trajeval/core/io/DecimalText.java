package org.trajeval.core.io;

import java.util.Locale;

/**
 * The one number syntax every reader accepts, {@code [+-]? (d+ [.d*] | .d+) ([eE] [+-]? d+)?},
 * and its conversion to the nearest double (the semantics of {@link Double#parseDouble}, which
 * are also those of numpy's and Python's {@code float}). Narrower than both Java's grammar (no
 * hex, no {@code d}/{@code f} suffix, no "NaN"/"Infinity") and Python's (no "inf", no
 * underscores), so that a file reads the same here and in evo.
 *
 * <p>The byte version parses in place ({@link DecimalScanner}: Clinger's exact path, else
 * fastdoubleparser); the String version with the JDK. Both give bit-identical doubles.
 */
final class DecimalText {
    private DecimalText() {
    }

    /** @return true if {@code b[from..to)} is a decimal number in the accepted syntax */
    static boolean isDecimal(byte[] b, int from, int to) {
        int i = from;
        if (i < to && (b[i] == '+' || b[i] == '-')) {
            i++;
        }
        int digits = 0;
        while (i < to && b[i] >= '0' && b[i] <= '9') {
            i++;
            digits++;
        }
        if (i < to && b[i] == '.') {
            i++;
            while (i < to && b[i] >= '0' && b[i] <= '9') {
                i++;
                digits++;
            }
        }
        if (digits == 0) {
            return false;
        }
        if (i < to && (b[i] == 'e' || b[i] == 'E')) {
            i++;
            if (i < to && (b[i] == '+' || b[i] == '-')) {
                i++;
            }
            int expDigits = 0;
            while (i < to && b[i] >= '0' && b[i] <= '9') {
                i++;
                expDigits++;
            }
            if (expDigits == 0) {
                return false;
            }
        }
        return i == to;
    }

    /** @return true if {@code s} is a decimal number in the accepted syntax */
    static boolean isDecimal(CharSequence s) {
        int n = s.length();
        byte[] b = new byte[n];
        for (int i = 0; i < n; i++) {
            char c = s.charAt(i);
            b[i] = c < 128 ? (byte) c : (byte) '?';
        }
        return isDecimal(b, 0, n);
    }

    /** @return the double nearest to {@code b[from..to)}, which must satisfy {@link #isDecimal(byte[], int, int)} */
    static double parse(byte[] b, int from, int to) {
        DecimalScanner scanner = new DecimalScanner();
        scanner.scan(b, from, to);
        return scanner.value();
    }

    /** @return the double nearest to {@code s}, which must satisfy {@link #isDecimal(CharSequence)} */
    static double parse(String s) {
        return Double.parseDouble(s);
    }

    /** @return true if the text spells a non-finite value ("nan", "-inf", "Infinity", ...) */
    static boolean spellsNonFinite(String text) {
        String s = text.trim().toLowerCase(Locale.ROOT);
        if (s.startsWith("+") || s.startsWith("-")) {
            s = s.substring(1);
        }
        return s.equals("nan") || s.equals("inf") || s.equals("infinity") || s.equals("1.#inf")
                || s.equals("1.#qnan") || s.equals("-nan(ind)");
    }
}
