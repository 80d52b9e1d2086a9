package org.trajeval.core.io;

import java.util.ArrayList;
import java.util.List;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * Planar CSV with a header row ({@code t,x,y,yaw} by default; names, delimiter and time unit
 * from the {@link CsvLayout}; extra columns ignored; {@code #} comment lines and blank lines
 * skipped). Plain numeric files take the fast path: bytes parsed in place, no object per line.
 * A file with a quote character anywhere is read again with full CSV semantics
 * ({@link QuotedCsvReader}, Commons CSV); both paths give bit-identical doubles.
 */
final class CsvTrajectoryReader {
    /** The remedy for stamps in the wrong unit. */
    static final String TIME_UNIT_REMEDY = "pass --time-unit %s";

    private CsvTrajectoryReader() {
    }

    /** As {@link #read(ByteSource, String, ReadOptions, String)}, a big plain file in blocks on {@code threads}. */
    static LoadedTrajectory read(ByteSource file, String source, ReadOptions options, String reason,
            ReadThreads threads) {
        if (options.order() == TimestampOrder.REFUSE_UNSORTED && options.csv().delimiter() <= 127) {
            LoadedTrajectory t = BlockRead.read(file, source, options, new Blocks(source, options, reason), threads);
            if (t != null) {
                return t;
            }
        }
        return read(file, source, options, reason);
    }

    static LoadedTrajectory read(ByteSource file, String source, ReadOptions options, String reason) {
        CsvLayout layout = options.csv();
        if (layout.delimiter() > 127) {
            return QuotedCsvReader.read(file, source, options, reason);
        }
        try {
            return readPlain(file, source, options, reason);
        } catch (NeedsQuotedCsv quoted) {
            return QuotedCsvReader.read(file, source, options, reason);
        }
    }

    /** The fast path: throws {@link NeedsQuotedCsv} at the first quote character. */
    static LoadedTrajectory readPlain(ByteSource file, String source, ReadOptions options, String reason) {
        CsvLayout layout = options.csv();
        try (ByteLines lines = ByteLines.open(file, source, options.maxBytes())) {
            NumericRows rows = new NumericRows(lines, source, (byte) layout.delimiter(), true);
            if (!rows.nextContentLine()) {
                throw FileProblems.empty(source, "it has not even a header line (expected "
                        + String.join(String.valueOf(layout.delimiter()), layout.timeColumn(), layout.xColumn(),
                                layout.yColumn(), layout.yawColumn()) + ")");
            }
            List<String> header = new ArrayList<>(rows.fieldCount());
            for (int i = 0; i < rows.fieldCount(); i++) {
                header.add(rows.field(i));
            }
            CsvColumns columns = CsvColumns.locate(header, layout, source, rows.lineNumber());
            rows.select(columns.index(), columns.names(), columns.units());
            rows.requireFields(columns.fieldCount(), CsvColumns.describe(header, layout.delimiter()));
            PoseBuffer poses = new PoseBuffer(source, layout.timeColumn(), 4, options.order(),
                    options.duplicates(), options.maxPoses()).positions(layout.xColumn(), layout.yColumn());
            poses.sizeFrom(lines);
            TimeUnit unit = layout.timeUnit();
            double[] row = new double[4];
            while (readBatch(rows, poses, row, unit, source, layout.timeColumn())) {
                // batches of lines: the loop body is a method called many times, so the JIT compiles
                // it fully early instead of relying on on-stack replacement of one long loop (3x
                // faster on a cold JVM)
            }
            double[][] c = poses.finishUntrimmed("it holds only a header line");
            String sha = lines.finishSha256();
            return new LoadedTrajectory(source, TrajectoryFormat.CSV, reason,
                    PlanarTrajectory.ofFirst(poses.size(), c[0], c[1], c[2], c[3]), sha, false);
        }
    }

    private static final int BATCH_LINES = 4096;

    /** Reads up to {@link #BATCH_LINES} data lines; @return false at the end of the file. */
    static boolean readBatch(NumericRows rows, PoseBuffer poses, double[] row, TimeUnit unit, String source,
            String timeColumn) {
        for (int k = 0; k < BATCH_LINES; k++) {
            if (!rows.next(row)) {
                return false;
            }
            double stamp = row[0];
            row[0] = unit.toSeconds(stamp);
            if (TimeUnitCheck.implausible(row[0])) {
                throw TimeUnitCheck.refuse(source, rows.lineNumber(), timeColumn, stamp, unit, TIME_UNIT_REMEDY,
                        rows.selectedText(0));
            }
            int code = poses.add(row, rows.lineNumber());
            if (code != PoseBuffer.ACCEPTED) {
                throw poses.orderProblem(code, row[0], rows.lineNumber(), rows.selectedText(0));
            }
        }
        return true;
    }

    /** Refuses a delimiter that cannot separate fields. */
    static void checkDelimiter(char d) {
        if (d == '"' || d == '#' || d == '\n' || d == '\r' || d == '.' || d == '-' || d == '+'
                || Character.isLetterOrDigit(d)) {
            throw new InputException(null, 0, "delimiter", InputProblem.INVALID_OPTION,
                    "the CSV delimiter must not be a quote, '#', a line break, a digit, a letter, '.', '+' or '-'",
                    String.valueOf(d));
        }
    }

    /** The blocks of a plain CSV file: the header in the first block, its columns in every block. */
    static final class Blocks implements BlockRead.Format {
        private final String source;
        private final ReadOptions options;
        private final String reason;
        private final CsvLayout layout;
        private CsvColumns columns;
        private String describe;

        Blocks(String source, ReadOptions options, String reason) {
            this.source = source;
            this.options = options;
            this.reason = reason;
            this.layout = options.csv();
        }

        @Override
        public int columns() {
            return 4;
        }

        @Override
        public NumericRows first(ByteLines lines) {
            NumericRows rows = new NumericRows(lines, source, (byte) layout.delimiter(), true);
            if (!rows.nextContentLine()) {
                return null;
            }
            List<String> header = new ArrayList<>(rows.fieldCount());
            for (int i = 0; i < rows.fieldCount(); i++) {
                header.add(rows.field(i));
            }
            columns = CsvColumns.locate(header, layout, source, rows.lineNumber());
            describe = CsvColumns.describe(header, layout.delimiter());
            return select(rows);
        }

        @Override
        public NumericRows later(ByteLines lines) {
            return select(new NumericRows(lines, source, (byte) layout.delimiter(), true));
        }

        private NumericRows select(NumericRows rows) {
            rows.select(columns.index(), columns.names(), columns.units());
            rows.requireFields(columns.fieldCount(), describe);
            return rows;
        }

        @Override
        public PoseBuffer segment() {
            return new PoseBuffer(source, layout.timeColumn(), 4, TimestampOrder.REFUSE_UNSORTED, options.duplicates(),
                    options.maxPoses()).positions(layout.xColumn(), layout.yColumn());
        }

        @Override
        public boolean readBatch(NumericRows rows, PoseBuffer poses, double[] in, double[] row) {
            return CsvTrajectoryReader.readBatch(rows, poses, row, layout.timeUnit(), source, layout.timeColumn());
        }

        @Override
        public LoadedTrajectory result(int n, double[][] c, String sha256) {
            return new LoadedTrajectory(source, TrajectoryFormat.CSV, reason,
                    PlanarTrajectory.ofFirst(n, c[0], c[1], c[2], c[3]), sha256, false);
        }
    }
}
