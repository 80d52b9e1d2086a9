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
        if (from + SHORT_WINDOW <= b.length) {
            int end = scanShort(b, from, to, ANY_END);
            if (end != LONG_NUMBER) {
                return end;
            }
        }
        return scanAny(b, from, to);
    }

    /** Returned by {@link #scanShort} for a number it leaves to {@link #scan}. */
    static final int LONG_NUMBER = -1;
    /** Bytes {@link #scanShort} may read from its {@code from}. */
    static final int SHORT_WINDOW = 40;
    private static final long[] LONG_POWERS_OF_TEN = {
        1L, 10L, 100L, 1_000L, 10_000L, 100_000L, 1_000_000L, 10_000_000L, 100_000_000L};
    private static final long ZEROS = 0x3030303030303030L;
    private static final long ABOVE_NINE = 0x7676767676767676L;
    private static final long HIGH_BITS = 0x8080808080808080L;
    /** A {@code ends} argument of {@link #scanShort}: any byte but an exponent's may follow the number. */
    static final long ANY_END = -1L;
    /** Largest exponent digit count {@link #scanShort} reads. */
    private static final int SHORT_EXPONENT_DIGITS = 3;

    /**
     * @return the set of bytes 0..63 whose bit is set: a {@code ends} argument of {@link #scanShort}
     *     (bytes from 64 on cannot be in it)
     */
    static long byteSet(char... bytes) {
        long set = 0;
        for (char c : bytes) {
            if (c < 64) {
                set |= 1L << c;
            }
        }
        return set;
    }

    /**
     * The common case without a loop per digit: {@code [+-]? d* [. d*] ([eE] [+-]? d{1,3})?} with
     * at most 16 digits on each side of the point and 18 in all, followed by {@code to} or by a
     * byte in {@code ends}. Each run of up to eight digits is found and summed in one eight-byte
     * word (SWAR, as in fast_float), so a number such as {@code -31.499999} takes two words; the
     * byte after a run is read from the same word (no second load), and decides whether a point,
     * an exponent or the number's end follows. The value is {@code m / 10^f} (or
     * {@code m * 10^k}) for the significand {@code m} (all its digits read as one integer) and
     * {@code f} digits after the point less the exponent: one IEEE division or multiplication,
     * exact by Clinger when {@code m <= 2^53} and {@code |k| <= 22} (both operands are then exact
     * doubles); a larger {@code m} goes to fastdoubleparser (without an exponent: at most 18
     * digits, so never infinite), a larger {@code |k|} to {@link #scan}. A value found here is
     * always finite.
     *
     * <p>A number that runs past {@code to} (its digits went on in bytes that are not the field's),
     * or is followed by a byte not in {@code ends}, is left to {@link #scan}, as is anything else
     * unusual. Needs {@link #SHORT_WINDOW} readable bytes from {@code from}.
     *
     * @param ends the bytes that may follow the number before {@code to} (a {@link #byteSet}); the
     *     fast line parser passes its field ends, {@link #scan} none
     * @return the index just past the number, or {@link #LONG_NUMBER} for anything else
     */
    int scanShort(byte[] b, int from, int to, long ends) {
        int i = from;
        byte first = b[i];
        boolean negative = first == '-';
        if (negative || first == '+') {
            i++;
        }
        long raw = (long) LONGS.get(b, i);
        long t = raw - ZEROS;
        int n = digitRun(t);
        if (n == 8) {
            return scanLongInteger(b, from, to, ends, i, t, negative);
        }
        long m;
        long next; // the byte after the last digit read, minus '0', in its lowest byte
        int fracDigits = 0;
        if ((byte) (t >>> (n << 3)) == POINT) {
            // the point lies in the first word: the word from the next byte supplies the digits after
            // it, so one word holds the first eight digits of both sides, the point taken out
            long before = (1L << (n << 3)) - 1;
            long w = ((raw & before) | ((long) LONGS.get(b, i + 1) & ~before)) - ZEROS;
            int l = digitRun(w);
            if (l < 8) {
                m = leadingDigits(w, l);
                next = w >>> (l << 3);
                fracDigits = l - n;
            } else {
                long u = (long) LONGS.get(b, i + 9) - ZEROS;
                int l2 = digitRun(u);
                if (l2 < 8) {
                    m = sumDigits(w) * LONG_POWERS_OF_TEN[l2] + leadingDigits(u, l2);
                    next = u >>> (l2 << 3);
                    fracDigits = 8 + l2 - n;
                } else {
                    long v = (long) LONGS.get(b, i + 17) - ZEROS;
                    int l3 = digitRun(v);
                    if (l3 > 2) {
                        return LONG_NUMBER; // more than 18 digits
                    }
                    m = (sumDigits(w) * 100_000_000L + sumDigits(u)) * LONG_POWERS_OF_TEN[l3] + leadingDigits(v, l3);
                    next = v >>> (l3 << 3);
                    fracDigits = 16 + l3 - n;
                }
            }
            i += n + 1 + fracDigits;
        } else {
            m = leadingDigits(t, n);
            next = t >>> (n << 3);
            i += n;
        }
        return finish(b, from, to, ends, i, negative, m, next, n + fracDigits, fracDigits);
    }

    /** The byte '.' minus '0'. */
    private static final byte POINT = (byte) ('.' - '0');

    /** {@link #scanShort} for a number with eight or more digits before the point ({@code t}: the first eight). */
    private int scanLongInteger(byte[] b, int from, int to, long ends, int i, long t, boolean negative) {
        long u = (long) LONGS.get(b, i + 8) - ZEROS;
        int n2 = digitRun(u);
        if (n2 == 8) {
            return LONG_NUMBER;
        }
        long m = sumDigits(t) * LONG_POWERS_OF_TEN[n2] + leadingDigits(u, n2);
        long next = u >>> (n2 << 3);
        int intDigits = 8 + n2;
        i += intDigits;
        int fracDigits = 0;
        if ((byte) next == POINT) {
            long f = (long) LONGS.get(b, i + 1) - ZEROS;
            int k = digitRun(f);
            if (k < 8) {
                m = m * LONG_POWERS_OF_TEN[k] + leadingDigits(f, k);
                next = f >>> (k << 3);
                fracDigits = k;
            } else {
                long g = (long) LONGS.get(b, i + 9) - ZEROS;
                int k2 = digitRun(g);
                if (k2 == 8 || intDigits + 8 + k2 > 18) {
                    return LONG_NUMBER;
                }
                m = (m * 100_000_000L + sumDigits(f)) * LONG_POWERS_OF_TEN[k2] + leadingDigits(g, k2);
                next = g >>> (k2 << 3);
                fracDigits = 8 + k2;
            }
            i += 1 + fracDigits;
        }
        return finish(b, from, to, ends, i, negative, m, next, intDigits + fracDigits, fracDigits);
    }

    /**
     * The end of {@link #scanShort}: the number's digits are read ({@code m}, {@code digits} of
     * them, {@code fracDigits} after the point, {@code b[i]} the next byte, also the lowest byte of
     * {@code next} less '0'); checks what follows, reads an exponent, sets the value.
     */
    private int finish(byte[] b, int from, int to, long ends, int i, boolean negative, long m, long next, int digits,
            int fracDigits) {
        if (digits == 0 || digits > 18 || i > to) {
            return LONG_NUMBER;
        }
        if (i < to) {
            int c = (int) (next + '0') & 0xFF;
            if (c == 'e' || c == 'E') {
                return scanExponent(b, from, to, ends, i, negative, m, fracDigits);
            }
            if (ends != ANY_END && (c >= 64 || (ends >>> c & 1) == 0)) {
                return LONG_NUMBER;
            }
        }
        value = exactQuotient(b, from, i, negative, m, fracDigits);
        return i;
    }

    /**
     * The rest of {@link #scanShort} for a number with an exponent ({@code b[e]} is its 'e' or 'E'):
     * a sign and one to {@link #SHORT_EXPONENT_DIGITS} digits; {@code m * 10^(exponent - f)} when
     * that is exact (so always finite), else {@link #LONG_NUMBER}.
     */
    private int scanExponent(byte[] b, int from, int to, long ends, int e, boolean negative, long m, int fracDigits) {
        int j = e + 1;
        byte c = b[j];
        boolean negativeExponent = c == '-';
        if (negativeExponent || c == '+') {
            c = b[++j];
        }
        int expStart = j;
        int exponent = 0;
        while (c >= '0' && c <= '9') {
            if (j - expStart == SHORT_EXPONENT_DIGITS) {
                return LONG_NUMBER;
            }
            exponent = exponent * 10 + (c - '0');
            c = b[++j];
        }
        if (j == expStart || j > to || j < to && ends != ANY_END && (c >= 64 || (ends >>> c & 1) == 0)) {
            return LONG_NUMBER;
        }
        int k = (negativeExponent ? -exponent : exponent) - fracDigits;
        if (m > EXACT_SIGNIFICAND || k < -22 || k > 22) {
            return LONG_NUMBER; // not exact here, perhaps not even finite
        }
        double v = k < 0 ? (double) m / POWERS_OF_TEN[-k] : (double) m * POWERS_OF_TEN[k];
        value = negative ? -v : v;
        return j;
    }

    /** @return the number {@code b[from..end)} without exponent: {@code -+ m / 10^f}, exact when m <= 2^53 */
    private static double exactQuotient(byte[] b, int from, int end, boolean negative, long m, int fracDigits) {
        if (m <= EXACT_SIGNIFICAND) {
            double v = (double) m / POWERS_OF_TEN[fracDigits];
            return negative ? -v : v;
        }
        return JavaDoubleParser.parseDouble(b, from, end - from);
    }

    /**
     * @param t eight bytes minus '0' each, first byte lowest
     * @return how many of the leading bytes are digits (0..8); a byte is a digit exactly when
     *     {@code t} holds 0..9 there: 10..127 gain the high bit when 0x76 is added, 128..255 (and
     *     bytes below '0', which borrow) have it already. A borrow or carry only travels upwards,
     *     past the first non-digit, so the lowest flagged byte is exact.
     */
    private static int digitRun(long t) {
        long nonDigits = ((t + ABOVE_NINE) | t) & HIGH_BITS;
        return Long.numberOfTrailingZeros(nonDigits) >>> 3;
    }

    /**
     * @param t eight bytes minus '0' each, first byte lowest
     * @param n how many leading bytes are digits, 0..7
     * @return the number those n digits spell (0 when n = 0): they are moved to the top of the
     *     word, in two shifts so that n = 0 shifts out everything, and summed as eight digits
     */
    private static long leadingDigits(long t, int n) {
        return sumDigits((t << (56 - (n << 3))) << 8);
    }

    /** The significand accumulated by {@link #anyDigits}. */
    private long significand;
    /** False once {@link #anyDigits} dropped a digit past 18 significant ones. */
    private boolean exact;

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
