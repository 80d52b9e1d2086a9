package org.trajeval.core.io.bag;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.ReadOptions;

/**
 * A refused rosbag2 sqlite3 file gives back its connection: fuzzing (BagFuzzTest#sqlite3, 47 610
 * executions) ended in "Too many open files" because a file refused while its topics were read
 * (a row without a name) kept its JDBC connection, file descriptor and native memory open.
 */
class Sqlite3BagReaderTest {
    @TempDir
    Path dir;

    private static long openFiles() throws IOException {
        try (Stream<Path> s = Files.list(Path.of("/proc/self/fd"))) {
            return s.count();
        }
    }

    @Test
    void refusedDatabaseClosesItsConnectionEveryTime() throws IOException {
        Path db = dir.resolve("nameless-topic.db3");
        // the fuzz corpus unit with a topics row without a name (kept as a regression input)
        try (InputStream in = getClass().getResourceAsStream(
                "BagFuzzTestInputs/sqlite3/crash-24f4d0ea35b497015b4b80cc885cc7d106c27e16")) {
            Files.copy(in, db);
        }
        InputException first = assertThrows(InputException.class,
                () -> BagTrajectoryReader.read(db, BagReadOptions.of("/pose"), ReadOptions.defaults()));
        assertEquals(InputProblem.CORRUPT_BAG, first.problem(), first.getMessage());
        long before = openFiles();
        for (int i = 0; i < 300; i++) {
            assertThrows(InputException.class,
                    () -> BagTrajectoryReader.read(db, BagReadOptions.of("/pose"), ReadOptions.defaults()));
        }
        long after = openFiles();
        // each leaked connection kept the file open: 300 refusals would add 300 descriptors
        assertTrue(after - before < 20, "open files grew from " + before + " to " + after);
    }
}
