package org.trajeval.core.io;

import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.io.Reader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.security.DigestInputStream;
import java.security.MessageDigest;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.Iterator;
import java.util.List;
import org.apache.commons.csv.CSVFormat;
import org.apache.commons.csv.CSVParser;
import org.apache.commons.csv.CSVRecord;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * The CSV path with full CSV semantics (quoted fields, delimiters or line breaks inside quotes),
 * through Commons CSV. Same layout, checks and numbers as the fast path in
 * {@link CsvTrajectoryReader}; used only for files that have a quote character. A record's line
 * number is the line on which it ends.
 */
final class QuotedCsvReader {
    private QuotedCsvReader() {
    }

    static LoadedTrajectory read(ByteSource file, String source, ReadOptions options, String reason) {
        CsvLayout layout = options.csv();
        CSVFormat format = CSVFormat.DEFAULT.builder()
                .setDelimiter(layout.delimiter())
                .setCommentMarker('#')
                .setIgnoreEmptyLines(true)
                .setIgnoreSurroundingSpaces(true)
                .setTrim(true)
                .get();
        MessageDigest sha = ByteLines.sha256();
        InputStream raw;
        try {
            raw = file.open();
        } catch (IOException | SecurityException e) {
            throw FileProblems.unreadable(source, e);
        }
        try (InputStream in = new DigestInputStream(raw, sha);
                Reader reader = new InputStreamReader(in, StandardCharsets.UTF_8);
                CSVParser parser = CSVParser.parse(reader, format)) {
            PlanarTrajectory trajectory = parse(parser, source, options);
            in.transferTo(OutputStream.nullOutputStream());
            return new LoadedTrajectory(source, TrajectoryFormat.CSV, reason, trajectory,
                    HexFormat.of().formatHex(sha.digest()), false);
        } catch (IOException | UncheckedIOException e) {
            throw FileProblems.unreadable(source, e);
        }
    }

    private static PlanarTrajectory parse(CSVParser parser, String source, ReadOptions options) {
        CsvLayout layout = options.csv();
        Iterator<CSVRecord> records = parser.iterator();
        long[] lastEnd = {0};
        CSVRecord first = nextRecord(records, parser, source, lastEnd);
        if (first == null) {
            throw FileProblems.empty(source, "it has not even a header line");
        }
        List<String> header = new ArrayList<>(first.toList());
        if (!header.isEmpty() && header.get(0).startsWith("\uFEFF")) {
            header.set(0, header.get(0).substring(1).trim());
        }
        long headerLine = parser.getCurrentLineNumber();
        CsvColumns columns = CsvColumns.locate(header, layout, source, headerLine);
        PoseBuffer poses = new PoseBuffer(source, layout.timeColumn(), 4, options.order(),
                    options.duplicates(), options.maxPoses()).positions(layout.xColumn(), layout.yColumn());
        TimeUnit unit = layout.timeUnit();
        double[] row = new double[4];
        CSVRecord record;
        while ((record = nextRecord(records, parser, source, lastEnd)) != null) {
            long line = parser.getCurrentLineNumber();
            if (record.size() != columns.fieldCount()) {
                throw new InputException(source, line, null, InputProblem.WRONG_FIELD_COUNT,
                        "a line must have " + columns.fieldCount() + " fields ("
                                + CsvColumns.describe(header, layout.delimiter()) + "), this one has " + record.size(),
                        String.join(String.valueOf(layout.delimiter()), record.toList()));
            }
            for (int k = 0; k < 4; k++) {
                row[k] = number(record.get(columns.index()[k]), source, line, columns.names()[k], columns.units()[k]);
            }
            double stamp = row[0];
            row[0] = unit.toSeconds(stamp);
            String stampText = record.get(columns.index()[0]);
            if (TimeUnitCheck.implausible(row[0])) {
                throw TimeUnitCheck.refuse(source, line, layout.timeColumn(), stamp, unit,
                        CsvTrajectoryReader.TIME_UNIT_REMEDY, stampText);
            }
            int code = poses.add(row, line);
            if (code != PoseBuffer.ACCEPTED) {
                throw poses.orderProblem(code, row[0], line, stampText);
            }
        }
        double[][] c = poses.finish("it holds only a header line");
        return PlanarTrajectory.of(c[0], c[1], c[2], c[3]);
    }

    /** @param lastEnd holds the line on which the previous record ended; updated */
    private static CSVRecord nextRecord(Iterator<CSVRecord> records, CSVParser parser, String source, long[] lastEnd) {
        try {
            CSVRecord r = records.hasNext() ? records.next() : null;
            lastEnd[0] = parser.getCurrentLineNumber();
            return r;
        } catch (UncheckedIOException | IllegalStateException e) {
            // Commons CSV reports broken quoting this way ("EOF reached before encapsulated token finished")
            Throwable cause = e.getCause() != null ? e.getCause() : e;
            throw new InputException(source, lastEnd[0] + 1, null, InputProblem.UNREADABLE,
                    "the file is not valid CSV (" + cause.getMessage() + "); is a quote left open?", null, e);
        }
    }

    private static double number(String text, String source, long line, String column, String unit) {
        if (DecimalText.isDecimal(text)) {
            double v = DecimalText.parse(text);
            if (Double.isFinite(v)) {
                return v;
            }
        }
        boolean nonFinite = DecimalText.isDecimal(text) || DecimalText.spellsNonFinite(text);
        throw new InputException(source, line, column, nonFinite ? InputProblem.NOT_FINITE : InputProblem.NOT_A_NUMBER,
                "column '" + column + "' must be a " + (nonFinite ? "finite number" : "number") + " " + unit, text);
    }
}
