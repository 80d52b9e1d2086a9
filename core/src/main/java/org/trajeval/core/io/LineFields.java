package org.trajeval.core.io;

import java.util.Arrays;

/**
 * The fields of one line of text: where each begins and ends in the line's bytes. Fields are
 * separated by one delimiter byte, each trimmed of surrounding spaces and tabs, or by runs of
 * spaces and tabs ({@link #BLANKS}). No allocation once the arrays have grown to the field count.
 */
final class LineFields {
    /** Delimiter value meaning "runs of spaces and tabs". */
    static final byte BLANKS = 0;

    private final byte delimiter;
    private final boolean quotesNeedCsv;
    private int[] fieldStart = new int[32];
    private int[] fieldEnd = new int[32];
    private int count;

    /**
     * @param quotesNeedCsv when true a quote character anywhere in a line throws
     *     {@link NeedsQuotedCsv} (the CSV reader then switches to Commons CSV)
     */
    LineFields(byte delimiter, boolean quotesNeedCsv) {
        this.delimiter = delimiter;
        this.quotesNeedCsv = quotesNeedCsv;
    }

    /** Splits {@code b[from..to)}, the text of one line without its line end, into fields. */
    void split(byte[] b, int from, int to) {
        count = 0;
        if (delimiter == BLANKS) {
            int i = from;
            while (true) {
                while (i < to && (b[i] == ' ' || b[i] == '\t')) {
                    i++;
                }
                if (i >= to) {
                    break;
                }
                int s = i;
                while (i < to && b[i] != ' ' && b[i] != '\t') {
                    i++;
                }
                add(s, i);
            }
            return;
        }
        final byte d = delimiter;
        int s = from;
        if (quotesNeedCsv) {
            for (int i = from; i < to; i++) {
                byte c = b[i];
                if (c == d) {
                    addTrimmed(b, s, i);
                    s = i + 1;
                } else if (c == '"') {
                    throw new NeedsQuotedCsv();
                }
            }
        } else {
            for (int i = from; i < to; i++) {
                if (b[i] == d) {
                    addTrimmed(b, s, i);
                    s = i + 1;
                }
            }
        }
        addTrimmed(b, s, to);
    }

    private void addTrimmed(byte[] b, int s, int e) {
        while (s < e && (b[s] == ' ' || b[s] == '\t')) {
            s++;
        }
        while (e > s && (b[e - 1] == ' ' || b[e - 1] == '\t')) {
            e--;
        }
        add(s, e);
    }

    private void add(int s, int e) {
        if (count == fieldStart.length) {
            fieldStart = Arrays.copyOf(fieldStart, count * 2);
            fieldEnd = Arrays.copyOf(fieldEnd, count * 2);
        }
        fieldStart[count] = s;
        fieldEnd[count] = e;
        count++;
    }

    /** @return the number of fields of the line last split */
    int count() {
        return count;
    }

    /** @return the offset of field {@code i}'s first byte */
    int start(int i) {
        return fieldStart[i];
    }

    /** @return the offset just past field {@code i}'s last byte */
    int end(int i) {
        return fieldEnd[i];
    }
}
