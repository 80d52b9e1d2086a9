package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.traj.SpatialTrajectory;

/** A read buffer reused by the next file on the same thread: the next file reads as in a fresh thread. */
class SpareBufferTest {
    @TempDir
    Path dir;

    @Test
    void theBufferGivenBackIsLentAgainButNeverToTwoReadersAtOnce() {
        byte[] first = SpareBuffer.take();
        byte[] nested = SpareBuffer.take(); // a second reader open on this thread: a fresh buffer
        assertNotSame(first, nested);
        SpareBuffer.giveBack(first);
        assertSame(first, SpareBuffer.take());
        SpareBuffer.giveBack(new byte[2 * SpareBuffer.LENGTH]); // grown for a long line: not kept
        assertEquals(SpareBuffer.LENGTH, SpareBuffer.take().length);
    }

    @Test
    void aShortFileReadAfterALongOneOnTheSameThreadReadsAsOnAFreshThread() throws Exception {
        // 1.6 MB of long numbers (the buffer is refilled and shifted), then short files whose last
        // line has no newline and ends where the long file had digits: a parser reading past the
        // bytes read would take the long file's digits as more of the number
        Path longFile = tum("long.tum", 20_000, 17, true);
        Path[] shortFiles = {tum("short.tum", 50, 1, false), tum("shortNewline.tum", 7, 3, true),
            Files.writeString(dir.resolve("one.tum"), "1 2 3 4 0 0 0 1")};
        ExecutorService one = Executors.newSingleThreadExecutor();
        try {
            for (Path shortFile : shortFiles) {
                String fresh = Executors.newSingleThreadExecutor().submit(() -> bits(shortFile)).get();
                String afterLong = one.submit(() -> {
                    bits(longFile);
                    return bits(shortFile);
                }).get();
                assertEquals(fresh, afterLong, shortFile.toString());
            }
        } finally {
            one.shutdownNow();
        }
    }

    @Test
    void aBadFileReadAfterALongOneIsRefusedAsOnAFreshThread() throws Exception {
        Path longFile = tum("long.tum", 20_000, 17, true);
        Path bad = Files.writeString(dir.resolve("bad.tum"), "1 2 3 4 0 0 0 1\n2 2 3 4 0 0 0 1x");
        String fresh = Executors.newSingleThreadExecutor().submit(() -> refusal(bad)).get();
        ExecutorService one = Executors.newSingleThreadExecutor();
        try {
            assertEquals(fresh, one.submit(() -> {
                bits(longFile);
                return refusal(bad);
            }).get());
        } finally {
            one.shutdownNow();
        }
    }

    /** @return a TUM file of {@code n} poses with {@code digits} decimals per value */
    private Path tum(String name, int n, int digits, boolean lastNewline) throws IOException {
        SplittableRandom rnd = new SplittableRandom(n * 31L + digits);
        StringBuilder s = new StringBuilder();
        String f = "%." + digits + "f";
        for (int i = 0; i < n; i++) {
            s.append(String.format(Locale.ROOT, f, 1.0 + i * 0.5));
            for (int k = 0; k < 3; k++) {
                s.append(' ').append(String.format(Locale.ROOT, f, rnd.nextDouble(-10, 10)));
            }
            s.append(" 0 0 0 1");
            if (i < n - 1 || lastNewline) {
                s.append('\n');
            }
        }
        return Files.writeString(dir.resolve(name), s);
    }

    /** @return the file's hash and every value's bits, as read on this thread */
    private static String bits(Path file) {
        LoadedTrajectory read = TrajectoryReader.read(file, ReadOptions.defaults());
        SpatialTrajectory t = (SpatialTrajectory) read.trajectory();
        StringBuilder s = new StringBuilder(read.sha256());
        for (int i = 0; i < t.size(); i++) {
            for (double v : new double[] {t.t(i), t.x(i), t.y(i), t.z(i), t.qw(i), t.qx(i), t.qy(i), t.qz(i)}) {
                s.append(' ').append(Long.toHexString(Double.doubleToRawLongBits(v)));
            }
        }
        return s.toString();
    }

    private static String refusal(Path file) {
        try {
            TrajectoryReader.read(file, ReadOptions.defaults());
            return "read";
        } catch (InputException e) {
            return e.getMessage();
        }
    }
}
