package org.trajeval.core.io;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVParser;
import org.apache.commons.csv.CSVRecord;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * A small CSV table of text (a list of pairs to score, say): a header line, then rows, each with
 * the line it starts on. RFC 4180 quoting, comma-separated, UTF-8; blank lines and lines starting
 * with {@code #} skipped; spaces around fields trimmed. Commons CSV stays behind this class.
 *
 * @param header the column names as written (trimmed)
 * @param rows the data rows in file order
 */
public record CsvTable(List<String> header, List<Row> rows) {

    /** @throws NullPointerException without header or rows */
    public CsvTable {
        header = List.copyOf(header);
        rows = List.copyOf(rows);
    }

    /**
     * One data row.
     *
     * @param line the 1-based line it starts on
     * @param fields the fields as written (trimmed, quotes removed)
     */
    public record Row(long line, List<String> fields) {
        /** @throws NullPointerException without fields */
        public Row {
            fields = List.copyOf(fields);
        }
    }

    /**
     * Reads a table of at most {@code maxBytes} bytes.
     *
     * @param source the name used in refusals
     * @throws InputException UNREADABLE (missing, unreadable, too large, not UTF-8, a broken quote),
     *     EMPTY (no header line), WRONG_FIELD_COUNT (a row with another number of fields than the header)
     */
    public static CsvTable read(Path path, String source, long maxBytes) {
        long size;
        try {
            size = Files.size(path);
        } catch (IOException | SecurityException e) {
            throw FileProblems.unreadable(source, e);
        }
        if (size > maxBytes) {
            throw FileProblems.tooManyBytes(source, size, maxBytes);
        }
        CSVFormat format = CSVFormat.DEFAULT.builder().setCommentMarker('#').setIgnoreEmptyLines(true)
                .setIgnoreSurroundingSpaces(true).setTrim(true).get();
        try (InputStream in = Files.newInputStream(path);
                Reader reader = new InputStreamReader(in, StandardCharsets.UTF_8.newDecoder()
                        .onMalformedInput(CodingErrorAction.REPORT).onUnmappableCharacter(CodingErrorAction.REPORT));
                CSVParser parser = CSVParser.parse(reader, format)) {
            List<String> header = null;
            List<Row> rows = new ArrayList<>();
            for (CSVRecord r : parser) {
                List<String> fields = r.toList();
                long line = parser.getCurrentLineNumber() - (countLineBreaks(fields));
                if (header == null) {
                    header = fields;
                    continue;
                }
                if (fields.size() != header.size()) {
                    throw new InputException(source, line, null, InputProblem.WRONG_FIELD_COUNT, "a row must have "
                            + header.size() + " fields, as the header (" + String.join(",", header) + "), this one has "
                            + fields.size(), String.join(",", fields));
                }
                rows.add(new Row(line, fields));
            }
            if (header == null) {
                throw new InputException(source, 0, null, InputProblem.EMPTY, "the table must start with a header "
                        + "line naming its columns; the file holds only comment or blank lines", null);
            }
            return new CsvTable(header, rows);
        } catch (IOException | UncheckedIOException | IllegalStateException e) {
            throw FileProblems.unreadable(source, e);
        }
    }

    /** @return the line breaks inside quoted fields (the parser's line number is that of the record's end) */
    private static int countLineBreaks(List<String> fields) {
        int n = 0;
        for (String f : fields) {
            for (int i = 0; i < f.length(); i++) {
                if (f.charAt(i) == '\n') {
                    n++;
                }
            }
        }
        return n;
    }
}
