package org.trajeval.core.io;

import ch.randelshofer.fastdoubleparser.JavaDoubleParser;

/**
 * Scans a decimal number in place, {@code [+-]? (d+ [.d*] | .d+) ([eE] [+-]? d+)?}, and gives
 * the double nearest to it (the semantics of {@link Double#parseDouble} and of Python's
 * {@code float}, so numbers read as evo reads them). No allocation.
 *
 * <p>Common short numbers take Clinger's exact path: a decimal significand m &le; 2^53 and a
 * power of ten 10^k with |k| &le; 22 are both exact doubles, so one IEEE multiplication or
 * division {@code m * 10^k} / {@code m / 10^-k} is the correctly rounded result. Every other
 * number (more digits, larger exponents) goes to fastdoubleparser's
 * {@code JavaDoubleParser.parseDouble(byte[], offset, length)}, which is also correctly rounded.
 */
final class DecimalScanner {
    private static final double[] POWERS_OF_TEN = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
    private static final long EXACT_SIGNIFICAND = 1L << 53;
    private static final long ACCUMULATE_LIMIT = (Long.MAX_VALUE - 9) / 10;
    private static final long EIGHT_DIGITS_LIMIT = (Long.MAX_VALUE - 99_999_999L) / 100_000_000L;
    private static final java.lang.invoke.VarHandle LONGS =
            java.lang.invoke.MethodHandles.byteArrayViewVarHandle(long[].class, java.nio.ByteOrder.LITTLE_ENDIAN);

    private double value;

    /**
     * Scans the longest prefix of {@code b[from..to)} that is a number.
     *
     * @return the index just past that prefix, or {@code from} if there is none; when larger than
     *     {@code from}, {@link #value()} holds the number (possibly infinite on overflow)
     */
    int scan(byte[] b, int from, int to) {
        if (from + 40 <= b.length) {
            int end = scanShort(b, from, to);
            if (end != LONG_NUMBER) {
                return end;
            }
        }
        return scanAny(b, from, to);
    }

    /** Returned by {@link #scanShort} for a number it leaves to {@link #scanAny}. */
    private static final int LONG_NUMBER = -1;
    private static final long[] LONG_POWERS_OF_TEN = {
        1L, 10L, 100L, 1_000L, 10_000L, 100_000L, 1_000_000L, 10_000_000L, 100_000_000L};
    private static final long ZEROS = 0x3030303030303030L;
    private static final long ABOVE_NINE = 0x7676767676767676L;
    private static final long HIGH_BITS = 0x8080808080808080L;

    /**
     * The common case without a loop per digit: a run of up to eight digits is found and summed in
     * one eight-byte word (SWAR), as in fast_float. Needs 40 readable bytes from {@code from}
     * (a sign, two runs of up to 16 digits, a point), and handles numbers of at most 18 significant
     * digits without an exponent on Clinger's exact path.
     *
     * @return as {@link #scan}, or {@link #LONG_NUMBER} for anything else
     */
    private int scanShort(byte[] b, int from, int to) {
        int i = from;
        boolean negative = false;
        if (i < to && (b[i] == '-' || b[i] == '+')) {
            negative = b[i] == '-';
            i++;
        }
        significand = 0;
        int intStart = i;
        i = shortDigits(b, i, to);
        int intDigits = i - intStart;
        int fracDigits = 0;
        if (i < to && b[i] == '.') {
            int j = shortDigits(b, i + 1, to);
            fracDigits = j - i - 1;
            if (intDigits + fracDigits > 0) {
                i = j;
            }
        }
        long m = significand;
        int digits = intDigits + fracDigits;
        if (digits == 0 || digits > 18 || (i < to && (b[i] >= '0' && b[i] <= '9' || b[i] == 'e' || b[i] == 'E'))) {
            return LONG_NUMBER;
        }
        if (m == 0) {
            value = negative ? -0.0 : 0.0;
        } else if (m <= EXACT_SIGNIFICAND && fracDigits <= 22) {
            double v = (double) m / POWERS_OF_TEN[fracDigits];
            value = negative ? -v : v;
        } else {
            value = JavaDoubleParser.parseDouble(b, from, i - from);
        }
        return i;
    }

    /** The significand accumulated by {@link #shortDigits} and {@link #anyDigits}. */
    private long significand;
    /** False once {@link #anyDigits} dropped a digit past 18 significant ones. */
    private boolean exact;

    /**
     * Appends the run of at most 16 digits at {@code b[i..to)} to {@link #significand}, eight at
     * a time (a longer run is left for the caller to see); needs 16 readable bytes from i.
     *
     * @return the index just past the digits taken
     */
    private int shortDigits(byte[] b, int i, int to) {
        long m = significand;
        for (int run = 0; run < 2; run++) {
            long t = (long) LONGS.get(b, i) - ZEROS;
            int n = digitRun(t, to - i);
            if (n == 0) {
                break;
            }
            m = m * LONG_POWERS_OF_TEN[n] + sumDigits(t << ((8 - n) << 3));
            i += n;
            if (n < 8) {
                break;
            }
        }
        significand = m;
        return i;
    }

    /**
     * Appends the run of digits at {@code b[i..to)}, however long, to {@link #significand}: eight at
     * a time while eight are there, then one by one; digits that would overflow it are dropped and
     * clear {@link #exact}.
     *
     * @return the index just past the digits
     */
    private int anyDigits(byte[] b, int i, int to) {
        long m = significand;
        while (i + 8 <= to && m <= EIGHT_DIGITS_LIMIT) {
            long eight = (long) LONGS.get(b, i);
            if (!isEightDigits(eight)) {
                break;
            }
            m = m * 100_000_000L + eightDigits(eight);
            i += 8;
        }
        while (i < to) {
            int d = b[i] - '0';
            if (d < 0 || d > 9) {
                break;
            }
            if (m <= ACCUMULATE_LIMIT) {
                m = m * 10 + d;
            } else {
                exact = false;
            }
            i++;
        }
        significand = m;
        return i;
    }

    /**
     * @param t eight bytes minus '0' each, first byte lowest
     * @param left bytes left before the end of the field
     * @return how many of the leading bytes are digits (0..8, at most {@code left}); a byte is a
     *     digit exactly when {@code t} holds 0..9 there: 10..127 gain the high bit when 0x76 is
     *     added, 128..255 (and bytes below '0', which borrow) have it already. A borrow or carry
     *     only travels upwards, past the first non-digit, so the lowest flagged byte is exact.
     */
    private static int digitRun(long t, int left) {
        long nonDigits = ((t + ABOVE_NINE) | t) & HIGH_BITS;
        return Math.min(Long.numberOfTrailingZeros(nonDigits) >>> 3, Math.max(left, 0));
    }

    /** @return the number whose decimal digits are the bytes of {@code d} (values 0..9, most significant lowest) */
    private static long sumDigits(long d) {
        d = (d * 10) + (d >>> 8);
        return (((d & 0x000000FF000000FFL) * (100 + (1_000_000L << 32)))
                + (((d >>> 16) & 0x000000FF000000FFL) * (1 + (10_000L << 32)))) >>> 32;
    }

    /** The general scan: any number of digits, exponents. */
    private int scanAny(byte[] b, int from, int to) {
        int i = from;
        boolean negative = false;
        if (i < to && (b[i] == '-' || b[i] == '+')) {
            negative = b[i] == '-';
            i++;
        }
        significand = 0;
        exact = true;
        int intStart = i;
        i = anyDigits(b, i, to);
        int intDigits = i - intStart;
        int fracDigits = 0;
        if (i < to && b[i] == '.') {
            int j = anyDigits(b, i + 1, to);
            fracDigits = j - i - 1;
            if (intDigits + fracDigits > 0) {
                i = j;
            }
        }
        long m = significand;
        if (intDigits + fracDigits == 0) {
            return from;
        }
        int exponent = 0;
        if (i < to && (b[i] == 'e' || b[i] == 'E')) {
            int j = i + 1;
            boolean negativeExponent = false;
            if (j < to && (b[j] == '-' || b[j] == '+')) {
                negativeExponent = b[j] == '-';
                j++;
            }
            int expStart = j;
            int e = 0;
            while (j < to) {
                int d = b[j] - '0';
                if (d < 0 || d > 9) {
                    break;
                }
                if (e < 100_000) {
                    e = e * 10 + d;
                }
                j++;
            }
            if (j > expStart) {
                exponent = negativeExponent ? -e : e;
                i = j;
            }
        }
        int k = exponent - fracDigits;
        if (exact && m == 0) {
            value = negative ? -0.0 : 0.0;
        } else if (exact && m <= EXACT_SIGNIFICAND && k >= -22 && k <= 22) {
            double v = k < 0 ? (double) m / POWERS_OF_TEN[-k] : (double) m * POWERS_OF_TEN[k];
            value = negative ? -v : v;
        } else {
            value = JavaDoubleParser.parseDouble(b, from, i - from);
        }
        return i;
    }

    /** @return true if all eight bytes (little-endian) are ASCII digits (fast_float's test) */
    private static boolean isEightDigits(long v) {
        return ((v & 0xF0F0F0F0F0F0F0F0L) | (((v + 0x0606060606060606L) & 0xF0F0F0F0F0F0F0F0L) >>> 4))
                == 0x3333333333333333L;
    }

    /** @return the value of eight ASCII digits, first digit in the lowest byte (fast_float's SWAR sum) */
    private static long eightDigits(long v) {
        v -= 0x3030303030303030L;
        v = (v * 10) + (v >>> 8);
        return (((v & 0x000000FF000000FFL) * (100 + (1_000_000L << 32)))
                + (((v >>> 16) & 0x000000FF000000FFL) * (1 + (10_000L << 32)))) >>> 32;
    }

    /** @return the number found by the last successful {@link #scan} */
    double value() {
        return value;
    }
}
