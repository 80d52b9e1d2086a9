package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.HexFormat;
import java.util.SplittableRandom;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * A file that changes while it is read in blocks ({@link BlockRead}): it grows, shrinks, or is
 * rewritten in place at the same size. The block read either gives up (the caller reads the file
 * as a whole) or reports the SHA-256 of exactly the bytes whose values it returns.
 */
class BlockReadChangingFileTest extends ReadPoolFixture {

    @TempDir
    Path dir;

    @Test
    void fileGrowingWhileReadFallsBackToTheWholeRead() throws IOException {
        String text = BlockReadTest.tum(new SplittableRandom(14), 200, false);
        StringBuilder more = new StringBuilder();
        for (int i = 0; i < 30; i++) {
            more.append(1.4e9 + i).append(" 1 2 3 0 0 0 1\n");
        }
        Path f = Files.writeString(dir.resolve("grow.tum"), text);
        AtomicBoolean grown = new AtomicBoolean();
        ByteSource growing = new Changing(f, () -> {
            if (grown.compareAndSet(false, true)) {
                Files.writeString(f, more, StandardOpenOption.APPEND);
            }
        });
        LoadedTrajectory blocks = BlockReadHostileTest.tumInBlocks(growing, f, threads(500));
        assertTrue(grown.get());
        assertNull(blocks, "a size change while the blocks are read must fall back to the whole read");
    }

    @Test
    void fileShrinkingWhileReadFallsBackToTheWholeRead() throws IOException {
        String text = BlockReadTest.tum(new SplittableRandom(16), 200, false);
        Path f = Files.writeString(dir.resolve("shrink.tum"), text);
        int cut = text.indexOf('\n', text.length() / 2) + 1;
        AtomicBoolean shrunk = new AtomicBoolean();
        ByteSource shrinking = new Changing(f, () -> {
            if (shrunk.compareAndSet(false, true)) {
                Files.writeString(f, text.substring(0, cut));
            }
        });
        LoadedTrajectory blocks = BlockReadHostileTest.tumInBlocks(shrinking, f, threads(500));
        assertTrue(shrunk.get());
        assertNull(blocks, "a size change while the blocks are read must fall back to the whole read");
    }

    @Test
    void fileShrinkingAfterItsFirstBlocksWereReadFallsBackToTheWholeRead() throws IOException {
        String text = BlockReadTest.tum(new SplittableRandom(19), 200, false);
        Path f = Files.writeString(dir.resolve("shrinklate.tum"), text);
        int cut = text.indexOf('\n', text.length() / 3) + 1;
        AtomicBoolean shrunk = new AtomicBoolean();
        ByteSource shrunkMidway = new Changing(f, () -> { }) {
            @Override
            public InputStream open(long from) throws IOException {
                if (from > text.length() / 2 && shrunk.compareAndSet(false, true)) {
                    Files.writeString(f, text.substring(0, cut));
                }
                return super.open(from);
            }
        };
        LoadedTrajectory blocks = BlockReadHostileTest.tumInBlocks(shrunkMidway, f, threads(300));
        assertTrue(shrunk.get());
        assertNull(blocks, "a size change while the blocks are read must fall back to the whole read");
    }

    @Test
    void fileRewrittenAtTheSameSizeBetweenBlocksGivesTheHashOfTheBytesParsed() throws IOException {
        // blocks read in file order on this thread (the helpers run in place): the file is rewritten
        // just before the second block is read, so the first block holds the old values, the rest the new
        Path f = dir.resolve("rewrite.tum");
        LoadedTrajectory blocks = readRewritten(f, 31, new ReadThreads(Runnable::run, 2, 500), 1);
        assertNotNull(blocks, "the block read gave up");
        String[] versions = versions(31);
        byte[] parsed = parsedBytes(blocks, versions);
        assertNotEquals(versions[0], new String(parsed, StandardCharsets.UTF_8), "the rewrite fell before the read");
        assertNotEquals(versions[1], new String(parsed, StandardCharsets.UTF_8), "the rewrite fell after the read");
        assertHashAndValuesOf(parsed, blocks);
    }

    @Test
    void fileRewrittenAtTheSameSizeWhileThreeThreadsReadItGivesTheHashOfTheBytesParsed() throws IOException {
        for (int k = 0; k < 40; k++) { // rewritten when the k-th block is opened, whichever thread opens it
            Path f = dir.resolve("rewrite" + k + ".tum");
            LoadedTrajectory blocks = readRewritten(f, 40 + k, threads(200), 1 + k % 20);
            assertNotNull(blocks, "the block read gave up");
            assertHashAndValuesOf(parsedBytes(blocks, versions(40 + k)), blocks);
        }
    }

    /**
     * @return seeded TUM text and the same text rewritten: the digit after the first '.' of every tx
     *     changed, so the same stamps, line lengths and block edges, and each line tells its version by tx
     */
    private static String[] versions(int seed) {
        String a = BlockReadTest.tum(new SplittableRandom(seed), 200, false);
        StringBuilder b = new StringBuilder(a);
        for (int start = 0; start < b.length(); start = b.indexOf("\n", start) + 1) {
            int digit = b.indexOf(".", b.indexOf(" ", start)) + 1;
            b.setCharAt(digit, (char) ('0' + (b.charAt(digit) - '0' + 1) % 10));
        }
        return new String[] {a, b.toString()};
    }

    /** Reads file {@code f}, first {@code versions(seed)[0]}, rewritten in place to the second when block {@code at} is opened. */
    private static LoadedTrajectory readRewritten(Path f, int seed, ReadThreads threads, int at) throws IOException {
        String[] v = versions(seed);
        Files.writeString(f, v[0]);
        AtomicInteger opened = new AtomicInteger();
        AtomicBoolean rewritten = new AtomicBoolean();
        ByteSource source = new Changing(f, () -> { }) {
            @Override
            public InputStream open(long from) throws IOException {
                if (opened.getAndIncrement() == at && rewritten.compareAndSet(false, true)) {
                    Files.writeString(f, v[1], StandardOpenOption.WRITE); // in place: no truncation
                }
                return super.open(from);
            }
        };
        LoadedTrajectory blocks = BlockReadHostileTest.tumInBlocks(source, f, threads);
        assertTrue(rewritten.get(), "the file was not rewritten");
        assertEquals(v[1], Files.readString(f));
        return blocks;
    }

    /** @return the text whose values the block read returned: each line from the version its tx is of */
    private byte[] parsedBytes(LoadedTrajectory blocks, String[] versions) throws IOException {
        SpatialTrajectory got = (SpatialTrajectory) blocks.trajectory();
        String[][] lines = {versions[0].split("\n"), versions[1].split("\n")};
        SpatialTrajectory[] read = {spatial(versions[0]), spatial(versions[1])};
        assertEquals(lines[0].length, got.size());
        StringBuilder text = new StringBuilder();
        for (int i = 0; i < got.size(); i++) {
            long tx = Double.doubleToRawLongBits(got.x(i));
            int v = tx == Double.doubleToRawLongBits(read[0].x(i)) ? 0 : 1;
            assertEquals(Double.doubleToRawLongBits(read[v].x(i)), tx, "pose " + i + " is of neither version");
            text.append(lines[v][i]).append('\n');
        }
        return text.toString().getBytes(StandardCharsets.UTF_8);
    }

    private SpatialTrajectory spatial(String text) throws IOException {
        return (SpatialTrajectory) wholeRead(text.getBytes(StandardCharsets.UTF_8)).trajectory();
    }

    private LoadedTrajectory wholeRead(byte[] text) throws IOException {
        return TrajectoryReader.read(Files.write(Files.createTempFile(dir, "v", ".tum"), text), ReadOptions.defaults());
    }

    /** Asserts the block read's hash is the SHA-256 of {@code parsed} and its values are the whole read's of them. */
    private void assertHashAndValuesOf(byte[] parsed, LoadedTrajectory blocks) throws IOException {
        assertEquals(sha256(parsed), blocks.sha256(), "the hash is not of the bytes parsed");
        LoadedTrajectory whole = wholeRead(parsed);
        assertEquals(BlockReadHostileTest.describe(whole.trajectory()),
                BlockReadHostileTest.describe(blocks.trajectory()));
    }

    private static String sha256(byte[] bytes) {
        try {
            return HexFormat.of().formatHex(MessageDigest.getInstance("SHA-256").digest(bytes));
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException(e);
        }
    }

    /** A file that changes (grows, shrinks) just after the block read took its size. */
    private static class Changing extends FileSourceDouble {
        private final Change change;

        Changing(Path f, Change change) {
            super(f);
            this.change = change;
        }

        @Override
        public long size() throws IOException {
            long size = super.size();
            change.run();
            return size;
        }
    }

    private interface Change {
        void run() throws IOException;
    }
}
