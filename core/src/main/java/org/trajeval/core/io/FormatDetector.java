package org.trajeval.core.io;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Guesses a file's format from its extension and its first lines (at most {@link #HEAD_BYTES}),
 * first rule that applies:
 * <ol>
 * <li>first non-blank line {@code #timestamp...} with commas: EuRoC;</li>
 * <li>extension {@code .tum}: TUM;</li>
 * <li>first data line naming the CSV layout's columns (t, x, y, yaw): CSV;</li>
 * <li>16 or more comma-separated numbers, the first of nanosecond size (&ge; 1e17): EuRoC;</li>
 * <li>extension {@code .csv}: CSV (the reader then says which header column is missing);</li>
 * <li>12 numbers separated by spaces: KITTI; 8 numbers: TUM.</li>
 * </ol>
 */
final class FormatDetector {
    /** How much of the file is looked at (bytes). */
    static final int HEAD_BYTES = 1 << 16;
    /** Smallest first stamp taken for EuRoC nanoseconds (1e17 ns is 1973). */
    static final double NANOSECOND_STAMP = 1e17;
    private static final String CHOICES = "pass --format csv|tum|kitti|euroc|nclt|robotcar-ins|robotcar-vo|icl-nuim";

    /**
     * @param format the format chosen
     * @param reason what was seen, e.g. "auto: 8 numeric columns (TUM)"
     */
    record Detection(TrajectoryFormat format, String reason) {
    }

    private FormatDetector() {
    }

    static Detection detect(ByteSource file, String source, CsvLayout layout) {
        byte[] head = new byte[HEAD_BYTES];
        int n = 0;
        boolean complete;
        try (InputStream in = file.open()) {
            int r;
            while (n < head.length && (r = in.read(head, n, head.length - n)) > 0) {
                n += r;
            }
            complete = n < head.length || in.read() < 0;
        } catch (IOException | SecurityException e) {
            throw FileProblems.unreadable(source, e);
        }
        String text = new String(head, 0, n, StandardCharsets.UTF_8);
        if (text.startsWith("\uFEFF")) {
            text = text.substring(1);
        }
        String name = file.fileName().toLowerCase(Locale.ROOT);
        String ext = name.lastIndexOf('.') >= 0 ? name.substring(name.lastIndexOf('.') + 1) : "";

        String firstNonBlank = null;
        String firstData = null;
        long dataLine = 0;
        // the lines of the head up to the first data line: text between '\n's, the last one
        // (after the last '\n') left out when the file goes on past the head (a partial line),
        // unless it is the only one
        int from = 0;
        for (int i = 0; from >= 0; i++) {
            int nl = text.indexOf('\n', from);
            if (nl < 0 && !complete && i > 0) {
                break;
            }
            String line = (nl < 0 ? text.substring(from) : text.substring(from, nl)).strip();
            from = nl < 0 ? -1 : nl + 1;
            if (line.isEmpty()) {
                continue;
            }
            if (firstNonBlank == null) {
                firstNonBlank = line;
            }
            if (!line.startsWith("#")) {
                firstData = line;
                dataLine = i + 1L;
                break;
            }
        }
        if (firstNonBlank == null && complete) {
            throw FileProblems.empty(source, "it holds only blank lines");
        }
        if (firstNonBlank != null && firstNonBlank.replace(" ", "").startsWith("timestamp,ins_status,")) {
            return new Detection(TrajectoryFormat.ROBOTCAR_INS, "auto: header 'timestamp,ins_status,...' (RobotCar INS)");
        }
        if (firstNonBlank != null && firstNonBlank.replace(" ", "").startsWith("source_timestamp,destination_timestamp,")) {
            return new Detection(TrajectoryFormat.ROBOTCAR_VO, "auto: header 'source_timestamp,destination_timestamp,"
                    + "...' (RobotCar VO)");
        }
        if (name.endsWith(".gt.freiburg")) {
            return new Detection(TrajectoryFormat.ICL_NUIM, "auto: name *.gt.freiburg (ICL-NUIM ground truth)");
        }
        if (firstNonBlank != null && isEurocHeader(firstNonBlank)) {
            return new Detection(TrajectoryFormat.EUROC, "auto: first line starts with '#timestamp' (EuRoC header)");
        }
        if (ext.equals("tum")) {
            return new Detection(TrajectoryFormat.TUM, "auto: extension .tum (TUM)");
        }
        if (firstData == null) {
            if (complete) {
                throw FileProblems.empty(source, "it holds only comment lines");
            }
            throw unknown(source, 0, "no data line in the first " + HEAD_BYTES + " bytes", null);
        }
        List<String> header = splitTrimmed(firstData, layout.delimiter());
        if (header.contains(layout.timeColumn()) && header.contains(layout.xColumn())
                && header.contains(layout.yColumn()) && header.contains(layout.yawColumn())) {
            return new Detection(TrajectoryFormat.CSV, "auto: header names " + layout.timeColumn() + ", "
                    + layout.xColumn() + ", " + layout.yColumn() + ", " + layout.yawColumn() + " (CSV)");
        }
        List<String> commaFields = splitTrimmed(firstData, ',');
        if (commaFields.size() >= 16 && allNumbers(commaFields)
                && Double.parseDouble(commaFields.get(0)) >= NANOSECOND_STAMP) {
            return new Detection(TrajectoryFormat.EUROC, "auto: " + commaFields.size()
                    + " comma-separated numeric columns, the first of nanosecond size (EuRoC)");
        }
        if (ext.equals("csv")) {
            return new Detection(TrajectoryFormat.CSV, "auto: extension .csv (CSV)");
        }
        String[] words = firstData.split("[ \t]+");
        if (allNumbers(List.of(words))) {
            if (words.length == 12) {
                return new Detection(TrajectoryFormat.KITTI, "auto: 12 numeric columns (KITTI)");
            }
            if (words.length == 8) {
                return new Detection(TrajectoryFormat.TUM, "auto: 8 numeric columns (TUM)");
            }
            throw unknown(source, dataLine, words.length + " numeric columns (TUM has 8, KITTI 12)", firstData);
        }
        throw unknown(source, dataLine, "the first data line is neither numbers nor a CSV header naming "
                + String.join(String.valueOf(layout.delimiter()), layout.timeColumn(), layout.xColumn(),
                        layout.yColumn(), layout.yawColumn()), firstData);
    }

    private static boolean isEurocHeader(String line) {
        String s = line.substring(1).strip().toLowerCase(Locale.ROOT);
        return line.startsWith("#") && s.startsWith("timestamp") && line.indexOf(',') > 0;
    }

    private static List<String> splitTrimmed(String line, char delimiter) {
        List<String> out = new ArrayList<>();
        int s = 0;
        for (int i = 0; i <= line.length(); i++) {
            if (i == line.length() || line.charAt(i) == delimiter) {
                String f = line.substring(s, i).strip();
                if (f.length() >= 2 && f.startsWith("\"") && f.endsWith("\"")) {
                    f = f.substring(1, f.length() - 1).strip();
                }
                out.add(f);
                s = i + 1;
            }
        }
        return out;
    }

    private static boolean allNumbers(List<String> fields) {
        for (String f : fields) {
            if (!DecimalText.isDecimal(f)) {
                return false;
            }
        }
        return !fields.isEmpty();
    }

    private static InputException unknown(String source, long line, String what, String found) {
        return new InputException(source, line, null, InputProblem.UNKNOWN_FORMAT,
                "cannot tell the format (" + what + "); trajeval reads csv (header t,x,y,yaw), tum (8 numbers a line), "
                        + "kitti (12 numbers a line) and euroc ('#timestamp' header): " + CHOICES,
                found);
    }
}
