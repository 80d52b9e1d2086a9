package org.trajeval.core.fuzz;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.trajeval.core.InputException;
import org.trajeval.core.io.CsvLayout;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TimeUnit;
import org.trajeval.core.io.TimestampOrder;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.io.TrajectoryReader;

/**
 * Coverage-guided fuzzing of {@link TrajectoryReader#read} for every format and for format
 * detection. The contract under test: whatever the bytes, the reader returns a trajectory or
 * throws {@link InputException}; any other exception (or error) is a bug and fails the test.
 *
 * <p>In a normal test run (regression mode) each target replays its committed corpus from
 * {@code src/test/resources/org/trajeval/core/fuzz/ReaderFuzzTestInputs/<method>/}. With
 * {@code JAZZER_FUZZ=1} Jazzer mutates inputs under coverage feedback (see README.md).
 *
 * <p>The first bytes of an input choose the read options (order and duplicate policies, CSV
 * delimiter and time unit, a KITTI times file, tight limits), so the fuzzer explores them too.
 */
class ReaderFuzzTest {
    /** One scratch directory per JVM (in RAM when /dev/shm exists): creating one per input halves the rate. */
    private static final Path SCRATCH = scratchDirectory();

    @FuzzTest(maxDuration = "10m")
    void csv(FuzzedDataProvider data) throws IOException {
        readFuzzed(data, TrajectoryFormat.CSV, ".csv");
    }

    @FuzzTest(maxDuration = "10m")
    void tum(FuzzedDataProvider data) throws IOException {
        readFuzzed(data, TrajectoryFormat.TUM, ".txt");
    }

    @FuzzTest(maxDuration = "10m")
    void kitti(FuzzedDataProvider data) throws IOException {
        readFuzzed(data, TrajectoryFormat.KITTI, ".txt");
    }

    @FuzzTest(maxDuration = "10m")
    void euroc(FuzzedDataProvider data) throws IOException {
        readFuzzed(data, TrajectoryFormat.EUROC, ".csv");
    }

    @FuzzTest(maxDuration = "10m")
    void autoDetect(FuzzedDataProvider data) throws IOException {
        String[] extensions = {".csv", ".txt", ".tum", ".kitti", ""};
        readFuzzed(data, null, data.pickValue(extensions));
    }

    /** Chooses read options from the input, writes the rest to a file and reads it. */
    private static void readFuzzed(FuzzedDataProvider data, TrajectoryFormat format, String extension)
            throws IOException {
        int flags = data.consumeInt(0, 0xFFFF);
        ReadOptions options = ReadOptions.defaults().withFormat(format)
                .withOrder((flags & 1) != 0 ? TimestampOrder.SORT : TimestampOrder.REFUSE_UNSORTED)
                .withDuplicates((flags & 2) != 0 ? DuplicateTimestamps.KEEP : DuplicateTimestamps.REFUSE);
        if ((flags & 4) != 0) {
            // tight limits: the size and count refusals must be clean too
            options = options.withLimits(1 + (flags >>> 8), 1 + ((flags >>> 4) & 0xF));
        }
        char[] delimiters = {',', ';', '\t', ' '};
        TimeUnit[] units = TimeUnit.values();
        CsvLayout layout = new CsvLayout("t", "x", "y", "yaw", delimiters[(flags >>> 3) & 3],
                units[((flags >>> 5) & 7) % units.length]);
        options = options.withCsv(layout);
        Path file = SCRATCH.resolve("input" + extension);
        Path times = SCRATCH.resolve("times.txt");
        try {
            byte[] body = data.consumeRemainingAsBytes();
            if (format == TrajectoryFormat.KITTI && (flags & 0x800) != 0) {
                // the bytes after the first NUL are the times file
                int cut = indexOf(body, (byte) 0);
                byte[] poses = cut < 0 ? body : java.util.Arrays.copyOfRange(body, 0, cut);
                byte[] stamps = cut < 0 ? new byte[0] : java.util.Arrays.copyOfRange(body, cut + 1, body.length);
                Files.write(file, poses);
                Files.write(times, stamps);
                options = options.withKittiTimes(times);
            } else {
                Files.write(file, body);
            }
            try {
                TrajectoryReader.read(file, options);
            } catch (InputException expected) {
                // the documented refusal of a bad input
            }
        } finally {
            Files.deleteIfExists(file);
            Files.deleteIfExists(times);
        }
    }

    private static Path scratchDirectory() {
        try {
            Path shm = Path.of("/dev/shm");
            Path dir = Files.isDirectory(shm) && Files.isWritable(shm)
                    ? Files.createTempDirectory(shm, "trajeval-fuzz") : Files.createTempDirectory("trajeval-fuzz");
            dir.toFile().deleteOnExit();
            return dir;
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }

    private static int indexOf(byte[] a, byte b) {
        for (int i = 0; i < a.length; i++) {
            if (a[i] == b) {
                return i;
            }
        }
        return -1;
    }
}
