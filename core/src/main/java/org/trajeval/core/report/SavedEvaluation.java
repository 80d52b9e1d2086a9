package org.trajeval.core.report;

import com.fasterxml.jackson.core.io.NumberOutput;
import org.trajeval.core.InputException;
import java.io.BufferedReader;
import java.io.BufferedWriter;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.zip.Deflater;
import java.util.zip.GZIPInputStream;
import java.util.zip.GZIPOutputStream;
import org.trajeval.core.eval.Evaluation;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;

/**
 * One evaluation saved as a folder ({@code trajeval eval --save-series DIR}): the summary
 * {@code report.json}, the per-pose series {@code poses.csv.gz} and the per-pair series
 * {@code pairs.csv.gz}, and the relative errors per sub-trajectory length {@code segments.csv.gz}
 * (one row per segment: start time, length (m), translation (%), rotation (deg/m)). The tables are
 * gzip CSV with a header naming each unit; pandas reads one with
 * {@code pd.read_csv("DIR/poses.csv.gz")}. The time column is {@code t_s} (seconds from the first
 * pose) or {@code frame} (files without stamps). Numbers are written as their shortest round-trip
 * decimal (the text that reads back to the same double), so plots redrawn from a saved folder are
 * those of the run.
 *
 * @param report the summary
 * @param series the per-pose and per-pair series
 */
public record SavedEvaluation(EvaluationReport report, EvaluationSeries series) {
    /** File name of the summary. */
    public static final String REPORT = "report.json";
    /** File name of the per-pose table. */
    public static final String POSES = "poses.csv.gz";
    /** File name of the per-pair table. */
    public static final String PAIRS = "pairs.csv.gz";
    /** File name of the per-segment table (absent in folders saved before it was written: no segments). */
    public static final String SEGMENTS = "segments.csv.gz";

    private static final List<String> POSE_COLUMNS = List.of("ref_x_m", "ref_y_m", "ref_z_m", "est_x_m", "est_y_m",
            "est_z_m", "ate_trans_m", "ate_rot_rad");
    private static final List<String> PAIR_COLUMNS = List.of("rpe_trans_m", "rpe_rot_rad");
    private static final List<String> SEGMENT_COLUMNS = List.of("length_m", "trans_pct", "rot_deg_per_m");

    /**
     * Scores a pair keeping the per-pose data: what {@code eval --plot / --save-series} and the
     * pipeline's per-run plots draw from.
     *
     * @param subTrajectoryLengthsM lengths of the sub-trajectory errors (m), or null for 10 ... 50 %
     *     of the reference path
     */
    public static SavedEvaluation score(LoadedTrajectory reference, LoadedTrajectory estimate,
            EvaluationOptions options, double[] subTrajectoryLengthsM) {
        Evaluation e = Evaluator.run(reference, estimate, options);
        boolean frames = reference.indexTimestamps() || estimate.indexTimestamps();
        return new SavedEvaluation(e.report(), EvaluationSeries.of(e, frames, subTrajectoryLengthsM));
    }

    /** Writes the four files into {@code dir} (each atomically). */
    public void write(Path dir) {
        EvaluationSeries.Poses p = series.poses();
        EvaluationSeries.Pairs q = series.pairs();
        String time = "s".equals(series.timeUnit()) ? "t_s" : "frame";
        String horizon = "s".equals(series.timeUnit()) ? "horizon_s" : "horizon_frames";
        ReportJson.writeAtomically(dir.resolve(POSES), gzipCsv(time, POSE_COLUMNS, p.t(), p.refX(), p.refY(),
                p.refZ(), p.estX(), p.estY(), p.estZ(), p.ateTransM(), p.ateRotRad()));
        ReportJson.writeAtomically(dir.resolve(PAIRS), gzipCsv(time, List.of(horizon, "rpe_trans_m", "rpe_rot_rad"),
                q.t(), q.horizon(), q.rpeTransM(), q.rpeRotRad()));
        EvaluationSeries.Segments g = series.segments();
        ReportJson.writeAtomically(dir.resolve(SEGMENTS), gzipCsv(time, SEGMENT_COLUMNS, g.t(), g.lengthM(),
                g.transPct(), g.rotDegPerM()));
        ReportJson.writeAtomically(dir.resolve(REPORT), ReportJson.toJson(report) + "\n");
    }

    /**
     * Reads a folder written by {@link #write}.
     *
     * @throws InputException naming the file, line and column when a file is not what
     *     {@link #write} writes
     */
    public static SavedEvaluation read(Path dir) {
        Path json = dir.resolve(REPORT);
        EvaluationReport report;
        try {
            report = ReportJson.parseEvaluation(Files.readString(json));
        } catch (IOException e) {
            throw InputException.unreadable(json + ": cannot be read (" + e.getMessage() + ")", e);
        } catch (InputException e) {
            throw InputException.unreadable(json + ": " + e.getMessage(), e);
        }
        Table poses = readGzipCsv(dir.resolve(POSES), POSE_COLUMNS);
        Table pairs = readGzipCsv(dir.resolve(PAIRS), PAIR_COLUMNS);
        if (!poses.timeUnit.equals(pairs.timeUnit)) {
            throw InputException.unreadable(dir.resolve(PAIRS) + ":1: time column '" + pairs.header[0]
                    + "' expected to match " + POSES + "'s '" + poses.header[0] + "'");
        }
        EvaluationSeries.Segments segments = EvaluationSeries.Segments.NONE;
        if (Files.exists(dir.resolve(SEGMENTS))) {
            Table s = readGzipCsv(dir.resolve(SEGMENTS), SEGMENT_COLUMNS);
            if (!poses.timeUnit.equals(s.timeUnit)) {
                throw InputException.unreadable(dir.resolve(SEGMENTS) + ":1: time column '" + s.header[0]
                        + "' expected to match " + POSES + "'s '" + poses.header[0] + "'");
            }
            for (int r = 0; r < s.columns[1].length; r++) {
                if (!(s.columns[1][r] > 0)) {
                    throw InputException.unreadable(dir.resolve(SEGMENTS) + ":" + (r + 2)
                            + ": column 'length_m' must be a number > 0 (m), found \"" + s.columns[1][r] + "\"");
                }
            }
            segments = new EvaluationSeries.Segments(s.columns[1], s.columns[0], s.columns[2], s.columns[3]);
        }
        double[][] c = poses.columns;
        double[][] d = pairs.columns;
        return new SavedEvaluation(report, new EvaluationSeries(poses.timeUnit,
                new EvaluationSeries.Poses(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8]),
                new EvaluationSeries.Pairs(d[0], d[1], d[2], d[3]), segments));
    }

    /**
     * A gzip CSV table streamed to {@code out}: numbers as their shortest round-trip decimal
     * (Jackson's Schubfach writer: the text Java 19+ {@code Double.toString} gives, several times
     * faster than Java 17's), empty for a non-finite value; gzip at its fastest level (a series of
     * 10^6 poses compresses about as well, several times sooner).
     */
    private static ReportJson.Content gzipCsv(String time, List<String> names, double[]... columns) {
        return out -> {
            GZIPOutputStream gz = new GZIPOutputStream(out, 1 << 16) {
                {
                    def.setLevel(Deflater.BEST_SPEED);
                }
            };
            Writer w = new BufferedWriter(new OutputStreamWriter(gz, StandardCharsets.US_ASCII), 1 << 16);
            w.write(time);
            for (String n : names) {
                w.write(',');
                w.write(n);
            }
            w.write('\n');
            for (int r = 0; r < columns[0].length; r++) {
                for (int c = 0; c < columns.length; c++) {
                    if (c > 0) {
                        w.write(',');
                    }
                    double v = columns[c][r];
                    if (Double.isFinite(v)) {
                        w.write(NumberOutput.toString(v, true));
                    }
                }
                w.write('\n');
            }
            w.flush();
            gz.finish();
        };
    }

    /** A table read back: time unit from the first column's name, then the columns. */
    private record Table(String timeUnit, String[] header, double[][] columns) {
    }

    private static Table readGzipCsv(Path file, List<String> expected) {
        try (BufferedReader r = new BufferedReader(new InputStreamReader(
                new GZIPInputStream(Files.newInputStream(file), 1 << 16), StandardCharsets.UTF_8))) {
            String head = r.readLine();
            String[] header = head == null ? new String[0] : head.split(",", -1);
            String unit = header.length == 0 ? "" : switch (header[0]) {
                case "t_s" -> "s";
                case "frame" -> "frame";
                default -> "";
            };
            List<String> rest = header.length == 0 ? List.of() : Arrays.asList(header).subList(1, header.length);
            boolean pairs = expected == PAIR_COLUMNS;
            List<String> want = pairs ? List.of("s".equals(unit) ? "horizon_s" : "horizon_frames", "rpe_trans_m",
                    "rpe_rot_rad") : expected;
            if (unit.isEmpty() || !rest.equals(want)) {
                throw InputException.unreadable(file + ":1: header expected \"t_s|frame," + String.join(",", want)
                        + "\", found \"" + (head == null ? "" : head) + "\"");
            }
            int cols = header.length;
            double[][] out = new double[cols][1024];
            int n = 0;
            String line;
            while ((line = r.readLine()) != null) {
                String[] f = line.split(",", -1);
                if (f.length != cols) {
                    throw InputException.unreadable(file + ":" + (n + 2) + ": " + cols + " fields expected, found "
                            + f.length);
                }
                if (n == out[0].length) {
                    for (int c = 0; c < cols; c++) {
                        out[c] = Arrays.copyOf(out[c], 2 * n);
                    }
                }
                for (int c = 0; c < cols; c++) {
                    try {
                        out[c][n] = f[c].isEmpty() ? Double.NaN : Double.parseDouble(f[c]);
                    } catch (NumberFormatException e) {
                        throw InputException.unreadable(file + ":" + (n + 2) + ": column '" + header[c]
                                + "' must be a number, found \"" + f[c] + "\"");
                    }
                }
                n++;
            }
            for (int c = 0; c < cols; c++) {
                out[c] = Arrays.copyOf(out[c], n);
            }
            return new Table(unit, header, out);
        } catch (IOException e) {
            throw InputException.unreadable(file + ": cannot be read as gzip CSV (" + e.getMessage() + ")", e);
        }
    }
}
