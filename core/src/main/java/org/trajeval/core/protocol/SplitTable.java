package org.trajeval.core.protocol;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Reads a split table: a CSV with a header naming {@code sequence_id}, {@code split} and,
 * optionally, {@code session_id} (without it each sequence is its own session, and only a
 * sequence listed in two splits leaks, as in the lesson's checker). Plain comma-separated fields,
 * no quoting; blank lines are skipped.
 */
public final class SplitTable {
    private SplitTable() {
    }

    /**
     * @throws InputException naming the file, line and column of the first bad row
     */
    public static List<SplitAssignment> read(Path file) {
        String source = file.toString();
        List<String> lines;
        try {
            lines = Files.readAllLines(file);
        } catch (NoSuchFileException e) {
            throw new InputException(source, 0, null, InputProblem.UNREADABLE, "split table does not exist", null, e);
        } catch (IOException e) {
            throw new InputException(source, 0, null, InputProblem.UNREADABLE,
                    "split table could not be read: " + e.getMessage(), null, e);
        }
        int h = 0;
        while (h < lines.size() && lines.get(h).isBlank()) {
            h++;
        }
        if (h == lines.size()) {
            throw new InputException(source, 0, null, InputProblem.EMPTY, "split table is empty", null);
        }
        List<String> header = Arrays.stream(lines.get(h).split(",", -1)).map(String::trim).toList();
        int seq = header.indexOf("sequence_id");
        int ses = header.indexOf("session_id");
        int spl = header.indexOf("split");
        for (String[] need : new String[][] {{"sequence_id", Integer.toString(seq)}, {"split", Integer.toString(spl)}}) {
            if (Integer.parseInt(need[1]) < 0) {
                throw new InputException(source, h + 1, need[0], InputProblem.MISSING_COLUMN,
                        "header must name the columns sequence_id, split (and optionally session_id)",
                        lines.get(h));
            }
        }
        List<SplitAssignment> rows = new ArrayList<>();
        for (int i = h + 1; i < lines.size(); i++) {
            String line = lines.get(i);
            if (line.isBlank()) {
                continue;
            }
            String[] f = line.split(",", -1);
            if (f.length != header.size()) {
                throw new InputException(source, i + 1, null, InputProblem.WRONG_FIELD_COUNT,
                        "expected " + header.size() + " comma-separated fields", line);
            }
            String id = f[seq].trim();
            String session = ses >= 0 ? f[ses].trim() : id;
            String splitText = f[spl].trim();
            if (id.isEmpty() || session.isEmpty()) {
                throw new InputException(source, i + 1, id.isEmpty() ? "sequence_id" : "session_id",
                        InputProblem.INVALID_CONFIGURATION, "ids must not be empty", line);
            }
            Split split = Split.fromKey(splitText);
            if (split == null) {
                throw new InputException(source, i + 1, "split", InputProblem.INVALID_CONFIGURATION,
                        "column 'split' must be train, val or test", splitText);
            }
            rows.add(new SplitAssignment(id, session, split));
        }
        return rows;
    }
}
