package org.trajeval.core.protocol;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.TextFiles;

/**
 * The resources a suite's runs needed, as measured by whoever ran the methods: a CSV file with the
 * header {@code method,sequence,seed,wall_time_s,peak_memory_mib} (any order) and optionally
 * {@code cpu_time_s} and {@code device}, one row per run. Read strictly: an unknown or repeated
 * column, a row with another number of fields, an unknown method or sequence, a seed that is not a
 * whole number, a time that is not a finite number &gt; 0 (s), a memory figure that is not a finite
 * number &ge; 0 (MiB), a device other than cpu or gpu, and a run listed twice are refused with the
 * file, line and column. Fields are plain (no quoting: names and numbers hold no commas).
 */
public final class ResourcesTable {
    /** Largest table read (bytes). */
    static final long MAX_BYTES = 64L << 20;
    private static final List<String> REQUIRED = List.of("method", "sequence", "seed", "wall_time_s",
            "peak_memory_mib");
    private static final List<String> OPTIONAL = List.of("cpu_time_s", "device");
    private static final Pattern WHOLE = Pattern.compile("[+-]?\\d{1,18}");
    private static final Pattern DECIMAL = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d{1,3})?");

    /**
     * One run's measured resources.
     *
     * @param line line of the row in the file
     * @param wallTimeS wall-clock time (s, &gt; 0)
     * @param peakMemoryMib peak resident memory (MiB, &ge; 0)
     * @param cpuTimeS CPU time (s), or null
     * @param device cpu or gpu, or null
     */
    public record Row(long line, double wallTimeS, double peakMemoryMib, Double cpuTimeS, String device) {
    }

    private final Map<String, Row> rows;

    private ResourcesTable(Map<String, Row> rows) {
        this.rows = rows;
    }

    /** @return the row of one run, or null ("budget unknown") */
    public Row of(String method, String sequence, long seed) {
        return rows.get(key(method, sequence, seed));
    }

    /** @return the number of rows */
    public int size() {
        return rows.size();
    }

    private static String key(String method, String sequence, long seed) {
        return method + "\u0000" + sequence + "\u0000" + seed;
    }

    /**
     * @param file the CSV file
     * @param methods the manifest's method names
     * @param sequences the manifest's sequence ids
     * @throws InputException on any problem, naming file, line and column
     */
    public static ResourcesTable read(Path file, Set<String> methods, Set<String> sequences) {
        return parse(TextFiles.readUtf8(file, "resources table", MAX_BYTES), file.toString(), methods, sequences);
    }

    /** Parses the table's text; {@code source} names it in refusals. */
    public static ResourcesTable parse(String text, String source, Set<String> methods, Set<String> sequences) {
        String[] lines = text.split("\r?\n", -1);
        if (lines.length == 0 || lines[0].isBlank()) {
            throw new InputException(source, 1, null, InputProblem.EMPTY, "resources table has no header "
                    + "(expected " + String.join(",", REQUIRED) + ")", null);
        }
        String[] header = lines[0].replace("\uFEFF", "").split(",", -1);
        Map<String, Integer> col = new LinkedHashMap<>();
        for (int i = 0; i < header.length; i++) {
            String h = header[i].trim();
            if (!REQUIRED.contains(h) && !OPTIONAL.contains(h)) {
                throw new InputException(source, 1, h, InputProblem.INVALID_CONFIGURATION, "unknown column '" + h
                        + "' in the resources table; expected " + String.join(", ", REQUIRED) + " and optionally "
                        + String.join(", ", OPTIONAL), h);
            }
            if (col.put(h, i) != null) {
                throw new InputException(source, 1, h, InputProblem.DUPLICATE_COLUMN, "column '" + h
                        + "' appears twice in the resources table", h);
            }
        }
        for (String r : REQUIRED) {
            if (!col.containsKey(r)) {
                throw new InputException(source, 1, r, InputProblem.MISSING_COLUMN, "the resources table needs a "
                        + "column '" + r + "' (header " + String.join(",", REQUIRED) + ")", lines[0]);
            }
        }
        Map<String, Row> rows = new HashMap<>();
        for (int i = 1; i < lines.length; i++) {
            long line = i + 1;
            if (lines[i].isBlank()) {
                continue;
            }
            String[] f = lines[i].split(",", -1);
            if (f.length != header.length) {
                throw new InputException(source, line, null, InputProblem.WRONG_FIELD_COUNT, "expected "
                        + header.length + " fields as the header, found " + f.length, lines[i]);
            }
            String method = f[col.get("method")].trim();
            if (!methods.contains(method)) {
                throw new InputException(source, line, "method", InputProblem.INVALID_CONFIGURATION,
                        "column 'method' must name a method of the manifest", method);
            }
            String sequence = f[col.get("sequence")].trim();
            if (!sequences.contains(sequence)) {
                throw new InputException(source, line, "sequence", InputProblem.INVALID_CONFIGURATION,
                        "column 'sequence' must name a sequence of the manifest", sequence);
            }
            String seedText = f[col.get("seed")].trim();
            if (!WHOLE.matcher(seedText).matches()) {
                throw new InputException(source, line, "seed", InputProblem.NOT_A_NUMBER,
                        "column 'seed' must be a whole number", seedText);
            }
            long seed = Long.parseLong(seedText);
            double wall = number(f[col.get("wall_time_s")], source, line, "wall_time_s", true, "s");
            double mem = number(f[col.get("peak_memory_mib")], source, line, "peak_memory_mib", false, "MiB");
            Double cpu = null;
            if (col.containsKey("cpu_time_s") && !f[col.get("cpu_time_s")].isBlank()) {
                cpu = number(f[col.get("cpu_time_s")], source, line, "cpu_time_s", false, "s");
            }
            String device = null;
            if (col.containsKey("device") && !f[col.get("device")].isBlank()) {
                device = f[col.get("device")].trim().toLowerCase(Locale.ROOT);
                if (!device.equals("cpu") && !device.equals("gpu")) {
                    throw new InputException(source, line, "device", InputProblem.INVALID_CONFIGURATION,
                            "column 'device' must be cpu or gpu", f[col.get("device")]);
                }
            }
            Row before = rows.put(key(method, sequence, seed), new Row(line, wall, mem, cpu, device));
            if (before != null) {
                throw new InputException(source, line, "seed", InputProblem.INVALID_CONFIGURATION, "run " + method
                        + "/" + sequence + "/seed " + seed + " is listed twice (lines " + before.line() + " and "
                        + line + ")", seedText);
            }
        }
        return new ResourcesTable(rows);
    }

    /** A resources table with no rows: every run's budget is unknown. */
    public static ResourcesTable empty() {
        return new ResourcesTable(Map.of());
    }

    private static double number(String text, String source, long line, String column, boolean positive,
            String unit) {
        String t = text.trim();
        if (!DECIMAL.matcher(t).matches()) {
            throw new InputException(source, line, column, InputProblem.NOT_A_NUMBER, "column '" + column
                    + "' must be a number (" + unit + ")", t);
        }
        double v = Double.parseDouble(t);
        if (!Double.isFinite(v) || (positive ? v <= 0.0 : v < 0.0)) {
            throw new InputException(source, line, column, Double.isFinite(v) ? InputProblem.OUT_OF_RANGE
                    : InputProblem.NOT_FINITE, "column '" + column + "' must be a finite number "
                    + (positive ? "> 0" : ">= 0") + " (" + unit + ")", t);
        }
        return v;
    }

    /** @return the rows, for tests */
    List<Row> rows() {
        return new ArrayList<>(rows.values());
    }
}
