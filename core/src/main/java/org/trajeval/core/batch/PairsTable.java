package org.trajeval.core.batch;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.CsvTable;
import org.trajeval.core.options.Setting;
import org.trajeval.core.options.SettingText;

/**
 * Reads a table of pairs (CSV with a header line): the columns {@code ref} and {@code est} name
 * the two files (relative paths are taken from the table's folder), a column named after a
 * setting of the options model ({@code alignment}, {@code max_diff_s}, ...) sets it for its row (an
 * empty cell leaves it unset), an optional {@code name} column names the row's report, and every
 * other column is passed through. Example:
 * <pre>
 * sequence,method,ref,est,alignment
 * fr1_xyz,orb,gt/fr1_xyz.txt,orb/fr1_xyz.txt,se3
 * fr1_xyz,vo,gt/fr1_xyz.txt,vo/fr1_xyz.txt,sim3
 * </pre>
 * The table itself is checked whole before any pair is scored: a missing {@code ref}/{@code est}
 * column, a column named twice, an empty {@code ref}/{@code est} cell or a bad or repeated name
 * refuses the table (a bad setting value or file only fails its row, when it is scored).
 */
public final class PairsTable {
    /** Column of the reference file. */
    public static final String REF = "ref";
    /** Column of the estimate file. */
    public static final String EST = "est";
    /** Optional column naming each row's report. */
    public static final String NAME = "name";
    /** What a report name may hold: letters, digits, '.', '_', '-', not starting with '.'. */
    private static final Pattern NAME_TEXT = Pattern.compile("[A-Za-z0-9_-][A-Za-z0-9._-]{0,127}");

    private PairsTable() {
    }

    /**
     * @param maxBytes the largest table accepted (bytes)
     * @return the rows, with file paths resolved against the table's folder
     * @throws InputException naming the table, line and column of the first problem
     */
    public static List<BatchPair> read(Path table, long maxBytes) {
        String source = table.toString();
        CsvTable t = CsvTable.read(table, source, maxBytes);
        List<String> header = t.header();
        Map<String, Integer> index = new HashMap<>();
        for (int c = 0; c < header.size(); c++) {
            Integer before = index.put(header.get(c), c);
            if (before != null) {
                throw new InputException(source, 1, header.get(c), InputProblem.DUPLICATE_COLUMN, "the header must "
                        + "name each column once, it names '" + header.get(c) + "' in fields " + (before + 1)
                        + " and " + (c + 1), String.join(",", header));
            }
        }
        for (String required : List.of(REF, EST)) {
            if (!index.containsKey(required)) {
                throw new InputException(source, 1, required, InputProblem.MISSING_COLUMN, "the header must name the "
                        + "columns 'ref' and 'est' (the two files of each pair; other columns are settings such as "
                        + "'alignment' or passed through)", String.join(",", header));
            }
        }
        Path folder = table.toAbsolutePath().getParent();
        Map<String, Long> names = new HashMap<>();
        List<BatchPair> pairs = new ArrayList<>();
        for (CsvTable.Row row : t.rows()) {
            String name = null;
            List<SettingText> settings = new ArrayList<>();
            Map<String, String> other = new LinkedHashMap<>();
            for (int c = 0; c < header.size(); c++) {
                String column = header.get(c);
                String cell = row.fields().get(c);
                if (column.equals(REF) || column.equals(EST)) {
                    if (cell.isEmpty()) {
                        throw new InputException(source, row.line(), column, InputProblem.INVALID_CONFIGURATION,
                                "column '" + column + "' must name a file", cell);
                    }
                } else if (column.equals(NAME)) {
                    name = checkedName(source, row.line(), cell, names);
                } else if (Setting.fromKey(column) != null) {
                    if (!cell.isEmpty()) {
                        settings.add(new SettingText(column, cell, column));
                    }
                } else {
                    other.put(column, cell);
                }
            }
            pairs.add(new BatchPair(row.line(), name, resolve(source, row.line(), REF, folder,
                    row.fields().get(index.get(REF))), resolve(source, row.line(), EST, folder,
                    row.fields().get(index.get(EST))), settings, other));
        }
        return pairs;
    }

    private static String checkedName(String source, long line, String cell, Map<String, Long> names) {
        if (!NAME_TEXT.matcher(cell).matches()) {
            throw new InputException(source, line, NAME, InputProblem.INVALID_CONFIGURATION, "column 'name' names the "
                    + "row's report file: 1 to 128 letters, digits, '.', '_' or '-', not starting with '.'", cell);
        }
        Long before = names.put(cell, line);
        if (before != null) {
            throw new InputException(source, line, NAME, InputProblem.INVALID_CONFIGURATION, "column 'name' must be "
                    + "unique (two reports cannot share a file); line " + before + " has it too", cell);
        }
        return cell;
    }

    private static String resolve(String source, long line, String column, Path folder, String file) {
        Path p;
        try {
            p = Path.of(file);
        } catch (java.nio.file.InvalidPathException e) {
            throw new InputException(source, line, column, InputProblem.INVALID_CONFIGURATION, "column '" + column
                    + "' must be a file path (" + e.getReason() + ")", file);
        }
        return p.isAbsolute() || folder == null ? p.toString() : folder.resolve(p).normalize().toString();
    }
}
