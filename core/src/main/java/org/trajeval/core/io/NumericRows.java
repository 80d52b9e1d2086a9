package org.trajeval.core.io;

import java.nio.charset.StandardCharsets;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Splits the lines of a {@link ByteLines} into fields and parses the selected fields as numbers,
 * in place and without allocating. Blank lines and lines whose first non-blank character is
 * {@code #} are skipped. Fields are separated by one delimiter byte (surrounding spaces and tabs
 * trimmed) or by runs of spaces and tabs ({@link #WHITESPACE}). Most lines take a one-pass path
 * that splits and scans together; the rest, and every refusal, the careful path ({@link LineFields}).
 */
final class NumericRows {
    /** Delimiter value meaning "runs of spaces and tabs". */
    static final byte WHITESPACE = LineFields.BLANKS;

    private final ByteLines lines;
    private final String source;
    private final byte delimiter;
    private final LineFields fields;

    private final DecimalScanner scanner = new DecimalScanner();
    private int[] select = new int[0];
    private int[] slotOfField = new int[0];
    private String[] names = new String[0];
    private String[] units = new String[0];
    private int exactFields = -1;
    private int minFields;
    private String layout = "";
    private long countSetAtLine;
    /** True when the selected fields are the first ones, in order ({@code select[k] == k}). */
    private boolean selectsPrefix;
    /** The bytes that end a number's field (a {@link DecimalScanner#byteSet}); 0 when the prefix paths do not apply. */
    private final long fieldEnds;

    /**
     * @param quotesNeedCsv when true a quote character anywhere in a line throws
     *     {@link NeedsQuotedCsv} (the CSV reader then switches to Commons CSV)
     */
    NumericRows(ByteLines lines, String source, byte delimiter, boolean quotesNeedCsv) {
        this.lines = lines;
        this.source = source;
        this.delimiter = delimiter;
        this.fields = new LineFields(delimiter, quotesNeedCsv);
        char d = (char) (delimiter & 0xFF);
        this.fieldEnds = delimiter == WHITESPACE ? DecimalScanner.byteSet(' ', '\t', '\n', '\r')
                : d < 64 && d != ' ' && d != '\t' ? DecimalScanner.byteSet(' ', '\t', '\n', '\r', d) : 0L;
    }

    /**
     * Chooses the fields to parse.
     *
     * @param fieldIndex 0-based field index of each selected column
     * @param columnNames name of each selected column (for messages)
     * @param columnUnits unit of each selected column, e.g. "(m)", or "" (for messages)
     */
    void select(int[] fieldIndex, String[] columnNames, String[] columnUnits) {
        this.select = fieldIndex.clone();
        this.names = columnNames.clone();
        this.units = columnUnits.clone();
        int max = -1;
        for (int f : fieldIndex) {
            max = Math.max(max, f);
        }
        this.slotOfField = new int[max + 1];
        java.util.Arrays.fill(slotOfField, -1);
        boolean prefix = true;
        for (int k = 0; k < fieldIndex.length; k++) {
            slotOfField[fieldIndex[k]] = k;
            prefix &= fieldIndex[k] == k;
        }
        this.selectsPrefix = prefix;
    }

    /** Every data line must have exactly {@code n} fields; {@code describe} says which, for messages. */
    void requireFields(int n, String describe) {
        this.exactFields = n;
        this.layout = describe;
    }

    /** The first data line must have at least {@code n} fields, every later one as many as the first. */
    void requireAtLeastFields(int n, String describe) {
        this.exactFields = -1;
        this.minFields = n;
        this.layout = describe;
    }

    /**
     * Advances to the next line that is neither blank nor a comment and splits it into fields.
     *
     * @return false at the end of the file
     */
    boolean nextContentLine() {
        if (!nextDataLine()) {
            return false;
        }
        fields.split(lines.buffer(), lines.start(), lines.end());
        return true;
    }

    private boolean nextDataLine() {
        while (lines.next()) {
            byte[] b = lines.buffer();
            int to = lines.end();
            int i = lines.start();
            while (i < to && (b[i] == ' ' || b[i] == '\t')) {
                i++;
            }
            if (i < to && b[i] != '#') {
                return true;
            }
        }
        return false;
    }

    /**
     * Reads the next data line into {@code row}: {@code row[k]} is the selected field {@code k}.
     *
     * @return false at the end of the file
     * @throws InputException on a wrong field count, a field that is not a number, or a non-finite one
     */
    boolean next(double[] row) {
        if (exactFields >= 0 && lines.position() < lines.completeLinesEnd() && parseInOnePass(row)) {
            return true;
        }
        if (!nextDataLine()) {
            return false;
        }
        parseCarefully(row);
        return true;
    }

    /**
     * The fast path: the line at {@link ByteLines#position()} is split and its numbers scanned in
     * one pass, which also finds its end (no separate search for the '\n'); the line is then taken
     * with {@link ByteLines#acceptLine}. Only called when the whole line is in the buffer, so every
     * byte looked at lies before the buffer's last '\n' (the scanner's words up to
     * {@link ByteLines#READ_AHEAD} bytes after it). Selections of the first fields in order take the
     * overloads below, without the field map; others the general loop here.
     *
     * @return false on anything unusual (a comment or blank line, a wrong count, a bad or
     *     non-finite number, a quote), leaving the line unread; {@link #next} then reads it on the
     *     careful path, which says what is wrong or reads what this path does not
     */
    private boolean parseInOnePass(double[] row) {
        final byte[] b = lines.buffer();
        final int bound = lines.completeLinesEnd();
        if (selectsPrefix && fieldEnds != 0 && bound + DecimalScanner.SHORT_WINDOW <= b.length) {
            if (delimiter != WHITESPACE) {
                return parseInOnePass(row, b, bound, delimiter);
            }
            if (exactFields == select.length) {
                return parseInOnePass(row, b, bound);
            }
        }
        final int[] slots = slotOfField;
        final int fields = exactFields;
        int p = lines.position();
        int q = p;
        while (b[q] == ' ' || b[q] == '\t') {
            q++;
        }
        if (b[q] == '#' || b[q] == '\n' || b[q] == '\r') {
            return false; // a comment or a blank line (or a rare '\r'): the careful path skips or reads it
        }
        int field = 0;
        int parsed = 0;
        int newline;
        if (delimiter == WHITESPACE) {
            while (true) {
                while (b[p] == ' ' || b[p] == '\t') {
                    p++;
                }
                if (b[p] == '\n') {
                    newline = p;
                    break;
                }
                if (b[p] == '\r' && b[p + 1] == '\n') {
                    newline = p + 1;
                    break;
                }
                if (field >= fields) {
                    return false;
                }
                int slot = field < slots.length ? slots[field] : -1;
                if (slot >= 0) {
                    int e = scanner.scan(b, p, bound);
                    if (e == p || !endsWhitespaceField(b, e)) {
                        return false;
                    }
                    double v = scanner.value();
                    if (Double.isInfinite(v)) {
                        return false;
                    }
                    row[slot] = v;
                    parsed++;
                    p = e;
                } else {
                    while (!endsWhitespaceField(b, p)) {
                        p++;
                    }
                }
                field++;
            }
        } else {
            final byte d = delimiter;
            while (true) {
                if (field >= fields) {
                    return false;
                }
                while (b[p] == ' ' || b[p] == '\t') {
                    p++;
                }
                int e;
                int slot = field < slots.length ? slots[field] : -1;
                if (slot >= 0) {
                    e = scanner.scan(b, p, bound);
                    if (e == p) {
                        return false;
                    }
                    while (b[e] == ' ' || b[e] == '\t') {
                        e++;
                    }
                    double v = scanner.value();
                    if (Double.isInfinite(v)) {
                        return false;
                    }
                    row[slot] = v;
                    parsed++;
                } else {
                    e = p;
                    while (b[e] != d && b[e] != '\n') {
                        if (b[e] == '"') {
                            return false;
                        }
                        e++; // a '\r' before the '\n' ends up in this unselected field, unread
                    }
                }
                field++;
                if (b[e] == d) {
                    p = e + 1;
                } else if (b[e] == '\n') {
                    newline = e;
                    break;
                } else if (b[e] == '\r' && b[e + 1] == '\n') {
                    newline = e + 1;
                    break;
                } else {
                    return false;
                }
            }
        }
        if (field != fields || parsed != select.length) {
            return false;
        }
        lines.acceptLine(newline);
        return true;
    }

    /**
     * {@link #parseInOnePass(double[])} for fields separated by spaces and tabs, every field
     * selected (TUM, KITTI): no field map, and each number's end checked in the scanner's own word
     * ({@link DecimalScanner#scanShort}). Every byte read lies before {@code bound}, or within
     * {@link DecimalScanner#SHORT_WINDOW} bytes after it, below {@code b.length} (a method of the
     * same name, so that the launcher's inlining directive for it applies).
     */
    private boolean parseInOnePass(double[] row, byte[] b, int bound) {
        final int fields = exactFields;
        final long ends = fieldEnds;
        final DecimalScanner s = scanner;
        int p = lines.position();
        byte c = b[p];
        for (int k = 0; k < fields; k++) {
            while (c == ' ' || c == '\t') {
                c = b[++p];
            }
            int e = s.scanShort(b, p, bound, ends);
            if (e < 0) {
                e = scanOther(b, p, bound);
                if (e < 0 || !endsWhitespaceField(b, e)) {
                    return false;
                }
            }
            row[k] = s.value();
            p = e;
            c = b[p];
        }
        while (c == ' ' || c == '\t') {
            c = b[++p];
        }
        return acceptLineEnd(b, p, c);
    }

    /**
     * {@link #parseInOnePass(double[])} for delimited fields whose selected ones come first, in
     * order (the planar CSV {@code t,x,y,yaw}, EuRoC): as {@link #parseInOnePass(double[], byte[], int)}, then the unselected
     * fields skipped up to their delimiter (a quote among them leaves the line to the careful path).
     */
    private boolean parseInOnePass(double[] row, byte[] b, int bound, byte d) {
        final int fields = exactFields;
        final int selected = select.length;
        final long ends = fieldEnds;
        final DecimalScanner s = scanner;
        int p = lines.position();
        byte c = b[p];
        for (int k = 0; k < selected; k++) {
            while (c == ' ' || c == '\t') {
                c = b[++p];
            }
            int e = s.scanShort(b, p, bound, ends);
            if (e < 0) {
                e = scanOther(b, p, bound);
                if (e < 0) {
                    return false;
                }
            }
            row[k] = s.value();
            p = e;
            c = b[p];
            while (c == ' ' || c == '\t') {
                c = b[++p];
            }
            if (k + 1 < fields) {
                if (c != d) {
                    return false;
                }
                c = b[++p];
            }
        }
        for (int f = selected; f < fields; f++) {
            while (c != d && c != '\n') {
                if (c == '"') {
                    return false;
                }
                c = b[++p]; // a '\r' before the '\n' ends up in this unselected field, unread
            }
            if (f + 1 < fields) {
                if (c != d) {
                    return false;
                }
                c = b[++p];
            }
        }
        return acceptLineEnd(b, p, c);
    }

    /** The prefix paths' number that {@link DecimalScanner#scanShort} leaves: @return its end, or -1 if none or not finite. */
    private int scanOther(byte[] b, int p, int bound) {
        int e = scanner.scan(b, p, bound);
        return e == p || Double.isInfinite(scanner.value()) ? -1 : e;
    }

    /** Takes the line if {@code c = b[p]} is its end ('\n', or '\r' before one). @return false if it is not */
    private boolean acceptLineEnd(byte[] b, int p, byte c) {
        if (c == '\n') {
            lines.acceptLine(p);
            return true;
        }
        if (c == '\r' && b[p + 1] == '\n') {
            lines.acceptLine(p + 1);
            return true;
        }
        return false;
    }

    /** @return true if {@code b[e]} ends a field separated by spaces and tabs: a blank, or the line end */
    private static boolean endsWhitespaceField(byte[] b, int e) {
        byte c = b[e];
        return c == ' ' || c == '\t' || c == '\n' || c == '\r' && b[e + 1] == '\n';
    }

    /** The careful path: split, check the count, check each selected field; throws on a problem. */
    private void parseCarefully(double[] row) {
        final byte[] b = lines.buffer();
        fields.split(b, lines.start(), lines.end());
        checkCount();
        for (int k = 0; k < select.length; k++) {
            int f = select[k];
            int s = fields.start(f);
            int e = fields.end(f);
            if (scanner.scan(b, s, e) != e || s == e || Double.isInfinite(scanner.value())) {
                throw badNumber(k, text(s, e));
            }
            row[k] = scanner.value();
        }
    }

    private void checkCount() {
        int count = fields.count();
        if (exactFields < 0) {
            if (count < minFields) {
                throw wrongCount("at least " + minFields + " fields");
            }
            exactFields = count;
            countSetAtLine = lines.lineNumber();
            return;
        }
        if (count != exactFields) {
            throw wrongCount(countSetAtLine > 0 ? exactFields + " fields like line " + countSetAtLine
                    : exactFields + " fields");
        }
    }

    private InputException wrongCount(String expected) {
        return new InputException(source, lines.lineNumber(), null, InputProblem.WRONG_FIELD_COUNT,
                "a line must have " + expected + " (" + layout + "), this one has " + fields.count(),
                lines.lineText());
    }

    private InputException badNumber(int k, String found) {
        boolean nonFinite = DecimalText.spellsNonFinite(found) || DecimalText.isDecimal(found);
        String unit = units[k].isEmpty() ? "" : " " + units[k];
        return new InputException(source, lines.lineNumber(), names[k],
                nonFinite ? InputProblem.NOT_FINITE : InputProblem.NOT_A_NUMBER,
                "column '" + names[k] + "' must be a " + (nonFinite ? "finite number" : "number") + unit, found);
    }

    /** @return number of fields of the current line */
    int fieldCount() {
        return fields.count();
    }

    /** @return field {@code i} of the current line as text (for headers and messages) */
    String field(int i) {
        return text(fields.start(i), fields.end(i));
    }

    /** @return the selected field {@code k} of the current line as text (for messages; splits the line again) */
    String selectedText(int k) {
        fields.split(lines.buffer(), lines.start(), lines.end());
        return select[k] < fields.count() ? field(select[k]) : "";
    }

    private String text(int s, int e) {
        return new String(lines.buffer(), s, e - s, StandardCharsets.UTF_8);
    }

    /** @return 1-based line number of the current line */
    long lineNumber() {
        return lines.lineNumber();
    }

    /** @return the current line as text (for messages) */
    String lineText() {
        return lines.lineText();
    }
}
