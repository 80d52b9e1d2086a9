package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Golden bad inputs: every {@code io/bad/<case>.expected.json} names the refusal its data file
 * {@code <case>.<ext>} must get (problem, 1-based line, column, a piece of the message) and the
 * read options to use. Adding a case is adding two files.
 */
class BadInputGoldenTest {
    private static final ObjectMapper JSON = new ObjectMapper();

    static Path badDir() {
        String project = System.getProperty("trajeval.projectDir", ".");
        return Path.of(project, "src", "test", "resources", "io", "bad");
    }

    @TestFactory
    Stream<DynamicTest> everyBadFileIsRefusedAsItsGoldenFileSays() throws IOException {
        Path dir = badDir();
        List<Path> expectations;
        try (Stream<Path> files = Files.list(dir)) {
            expectations = files.filter(p -> p.getFileName().toString().endsWith(".expected.json")).sorted().toList();
        }
        assertTrue(expectations.size() >= 50, "golden cases found in " + dir + ": " + expectations.size());
        return expectations.stream().map(json -> DynamicTest.dynamicTest(caseName(json), () -> check(json)));
    }

    private static String caseName(Path json) {
        String n = json.getFileName().toString();
        return n.substring(0, n.length() - ".expected.json".length());
    }

    private static void check(Path json) throws IOException {
        JsonNode expected = JSON.readTree(json.toFile());
        Path dir = json.getParent();
        Path data = expected.has("file") ? dir.resolve(expected.get("file").asText()) : dataFile(dir, caseName(json));
        ReadOptions options = options(expected.path("options"), dir);

        InputException e = assertThrows(InputException.class, () -> TrajectoryReader.read(data, options));

        assertEquals(InputProblem.valueOf(expected.get("problem").asText()), e.problem(), e.getMessage());
        assertEquals(expected.get("line").asLong(), e.line(), e.getMessage());
        if (expected.hasNonNull("column")) {
            assertEquals(expected.get("column").asText(), e.column(), e.getMessage());
        }
        if (expected.has("message_contains")) {
            assertTrue(e.getMessage().contains(expected.get("message_contains").asText()), e.getMessage());
        }
        assertFalse(e.getMessage().contains("\n"), "one line: " + e.getMessage());
        assertTrue(e.getMessage().startsWith(e.source() + ":"), "names the file: " + e.getMessage());
    }

    private static Path dataFile(Path dir, String caseName) throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            List<Path> matches = files.filter(p -> {
                String n = p.getFileName().toString();
                return n.startsWith(caseName + ".") && !n.endsWith(".expected.json") && !n.endsWith(".times")
                        && n.indexOf('.', caseName.length() + 1) < 0;
            }).toList();
            assertEquals(1, matches.size(), "one data file for case " + caseName + ": " + matches);
            return matches.get(0);
        }
    }

    static ReadOptions options(JsonNode o, Path dir) {
        ReadOptions options = ReadOptions.defaults();
        if (o.has("format")) {
            options = options.withFormat(TrajectoryFormat.valueOf(o.get("format").asText().toUpperCase(Locale.ROOT)));
        }
        if (o.has("order")) {
            options = options.withOrder(o.get("order").asText().equals("sort") ? TimestampOrder.SORT
                    : TimestampOrder.REFUSE_UNSORTED);
        }
        if (o.has("kitti_times")) {
            options = options.withKittiTimes(dir.resolve(o.get("kitti_times").asText()));
        }
        if (o.has("max_poses") || o.has("max_bytes")) {
            options = options.withLimits(o.path("max_bytes").asLong(ReadOptions.DEFAULT_MAX_BYTES),
                    o.path("max_poses").asLong(ReadOptions.DEFAULT_MAX_POSES));
        }
        CsvLayout csv = options.csv();
        if (o.has("delimiter") || o.has("time_unit")) {
            char delimiter = o.has("delimiter") ? o.get("delimiter").asText().charAt(0) : csv.delimiter();
            TimeUnit unit = o.has("time_unit") ? TimeUnit.valueOf(o.get("time_unit").asText().toUpperCase(Locale.ROOT))
                    : csv.timeUnit();
            options = options.withCsv(new CsvLayout(csv.timeColumn(), csv.xColumn(), csv.yColumn(), csv.yawColumn(),
                    delimiter, unit));
        }
        return options;
    }

    @Test
    void nonFiniteYawMessageNamesFileLineColumnUnitAndText() {
        Path file = badDir().resolve("csv-nan-yaw.csv");
        InputException e = assertThrows(InputException.class, () -> TrajectoryReader.read(file, ReadOptions.defaults()));
        assertEquals(file + ":3: column 'yaw' must be a finite number (rad), found \"nan\"", e.getMessage());
    }

    @Test
    void decreasingTimestampMessageSaysWhatToDo() {
        Path file = badDir().resolve("csv-decreasing.csv");
        InputException e = assertThrows(InputException.class, () -> TrajectoryReader.read(file, ReadOptions.defaults()));
        assertEquals(file + ":4: column 't' must be after line 3 (31.25 s): timestamps must increase."
                + " Sort the file, or pass --sort, found \"31.225\"", e.getMessage());
    }
}
