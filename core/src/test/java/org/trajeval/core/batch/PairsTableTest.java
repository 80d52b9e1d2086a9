package org.trajeval.core.batch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.options.SettingText;

/** The table of pairs: which column is what, paths, line numbers and refusals of the table itself. */
class PairsTableTest {
    @TempDir
    Path dir;

    private List<BatchPair> read(String text) throws IOException {
        Path p = dir.resolve("pairs.csv");
        Files.writeString(p, text);
        return PairsTable.read(p, 1 << 20);
    }

    private InputException refused(String text) {
        return assertThrows(InputException.class, () -> read(text));
    }

    @Test
    void settingColumnsSetTheirRowOtherColumnsPassThroughAndPathsAreTakenFromTheTablesFolder()
            throws IOException {
        List<BatchPair> rows = read("""
                # pairs of today
                sequence,ref,est,alignment,max_diff_s,note

                fr1,gt/a.txt,/abs/b.txt,se3,,"a, b"
                fr2,gt/c.txt,d.txt,,0.02,
                """);
        assertEquals(2, rows.size());
        BatchPair a = rows.get(0);
        assertEquals(4, a.line());
        assertEquals(dir.resolve("gt/a.txt").toString(), a.reference());
        assertEquals("/abs/b.txt", a.estimate());
        assertEquals(List.of(new SettingText("alignment", "se3", "alignment")), a.settings());
        assertEquals(Map.of("sequence", "fr1", "note", "a, b"), a.passThrough());
        assertEquals(List.of("sequence", "note"), List.copyOf(a.passThrough().keySet()));
        assertNull(a.name());
        assertEquals("line-0004", a.reportName());
        assertEquals(List.of(new SettingText("max_diff_s", "0.02", "max_diff_s")), rows.get(1).settings());
        assertEquals(5, rows.get(1).line());
    }

    @Test
    void aTableWithoutTheEstColumnIsRefusedAtItsHeader() {
        InputException e = refused("ref,estimate\na,b\n");
        assertEquals(InputProblem.MISSING_COLUMN, e.problem());
        assertEquals(1, e.line());
        assertEquals("est", e.column());
    }

    @Test
    void aRowWithAnotherFieldCountIsRefusedWithItsLine() {
        InputException e = refused("ref,est\na,b\nc\n");
        assertEquals(InputProblem.WRONG_FIELD_COUNT, e.problem());
        assertEquals(3, e.line());
    }

    @Test
    void reportNamesMustBeSafeFileNamesAndUnique() {
        assertEquals("name", refused("name,ref,est\n../x,a,b\n").column());
        InputException twice = refused("name,ref,est\nx,a,b\nx,c,d\n");
        assertEquals(3, twice.line());
        assertEquals(InputProblem.INVALID_CONFIGURATION, twice.problem());
    }

    @Test
    void anEmptyFileCellIsRefused() {
        InputException e = refused("ref,est\na,\n");
        assertEquals("est", e.column());
        assertEquals(2, e.line());
    }

    @Test
    void aColumnNamedTwiceIsRefused() {
        assertEquals(InputProblem.DUPLICATE_COLUMN, refused("ref,est,ref\na,b,c\n").problem());
    }
}
