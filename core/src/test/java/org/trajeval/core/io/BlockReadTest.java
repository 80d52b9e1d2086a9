package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import java.util.function.Function;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/**
 * Reading a file in blocks ({@link BlockRead}, {@link ReadThreads}) against reading it as a whole
 * ({@link TrajectoryReader#read(Path, ReadOptions)}, the general path): with blocks forced small,
 * so that every kind of line (header, comments, blank lines, CRLF, tabs, a byte-order mark, a last
 * line without newline) and every refusal falls at a block edge for some block size, the same
 * values bit for bit, the same SHA-256, and the same refusal (file, line, column, problem, message).
 */
class BlockReadTest extends ReadPoolFixture {
    private static final int[] BLOCK_SIZES = {1, 7, 29, 64, 97, 150, 333, 1000};

    @TempDir
    Path dir;

    @Test
    void cleanTumFileGivesTheWholeFileReadsBitsAndHashAtEveryBlockSize() throws IOException {
        Path f = write("a.tum", tum(new SplittableRandom(1), 300, true));
        for (int block : BLOCK_SIZES) {
            assertSameAndInBlocks(f, ReadOptions.defaults(), block,
                    reason -> new TumReader.Blocks(f.toString(), ReadOptions.defaults(), reason));
        }
    }

    @Test
    void cleanCsvFileGivesTheWholeFileReadsBitsAndHashAtEveryBlockSize() throws IOException {
        Path f = write("a.csv", csv(new SplittableRandom(2), 300, true));
        for (int block : BLOCK_SIZES) {
            if (block < 40) { // the first block holds no header: the file is read as a whole
                assertNull(assertSameOutcome(f, ReadOptions.defaults(), block));
                continue;
            }
            assertSameAndInBlocks(f, ReadOptions.defaults(), block,
                    reason -> new CsvTrajectoryReader.Blocks(f.toString(), ReadOptions.defaults(), reason));
        }
    }

    @Test
    void duplicateStampsKeptAcrossEveryBlockEdgeWhenAsked() throws IOException {
        StringBuilder sb = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i < 200; i++) {
            sb.append(i / 2).append(".5,").append(i).append(",0.25,-1e-3\n");
        }
        Path f = write("dup.csv", sb.toString());
        ReadOptions keep = ReadOptions.defaults().withDuplicates(DuplicateTimestamps.KEEP);
        for (int block : BLOCK_SIZES) {
            assertSameAndInBlocks(f, keep, block, reason -> new CsvTrajectoryReader.Blocks(f.toString(), keep, reason));
        }
    }

    @Test
    void quotedCsvIsReadWithFullCsvRulesAsAWhole() throws IOException {
        Path f = write("q.csv", csv(new SplittableRandom(3), 200, false).replace("\n7", "\n\"7\"").replace(
                "t,x,y,yaw", "\"t\",x,y,yaw"));
        assertTrue(Files.readString(f).contains("\""));
        for (int block : BLOCK_SIZES) {
            assertSameOutcome(f, ReadOptions.defaults(), block);
        }
    }

    @Test
    void everyRefusalIsTheWholeFileReadsFirstBadLineWhereverTheBlockEdgesFall() throws IOException {
        String good = tum(new SplittableRandom(4), 120, false);
        String[] lines = good.split("\n", -1);
        String[] bad = {"1.0 x 2 3 0 0 0 1", "0.0 0 0 0 0 0 0 1", "5e12 0 0 0 0 0 0 1", "%s 0 0 0 0.5 0 0 1",
            "%s 2e9 0 0 0 0 0 1", "%s 0 0 0 0 0 1", "%s 0 0 0 0 0 0 1 9", "%s 0 0 0 0 0 0 inf"};
        int k = 0;
        for (String b : bad) {
            for (int at : new int[] {3, 40, 77, 118}) {
                String[] copy = lines.clone();
                String stamp = copy[at].substring(0, copy[at].indexOf(' '));
                copy[at] = String.format(Locale.ROOT, b, stamp);
                Path f = write("bad" + k++ + ".tum", String.join("\n", copy));
                for (int block : BLOCK_SIZES) {
                    InputException e = assertSameOutcome(f, ReadOptions.defaults(), block);
                    assertNotNull(e, "line " + at + ": " + copy[at]);
                    assertNull(BlockRead.read(ByteSource.of(f), f.toString(), ReadOptions.defaults(),
                            new TumReader.Blocks(f.toString(), ReadOptions.defaults(), ""), threads(block)));
                }
            }
        }
    }

    @Test
    void repeatedStampAtEachBlockEdgeIsRefusedNamingTheLine() throws IOException {
        String good = csv(new SplittableRandom(5), 150, false);
        String[] lines = good.split("\n", -1);
        for (int at = 2; at < 150; at += 13) {
            String[] copy = lines.clone();
            copy[at] = copy[at - 1].substring(0, copy[at - 1].indexOf(',')) + copy[at].substring(copy[at].indexOf(','));
            Path f = write("rep" + at + ".csv", String.join("\n", copy));
            for (int block : BLOCK_SIZES) {
                InputException e = assertSameOutcome(f, ReadOptions.defaults(), block);
                assertNotNull(e);
            }
        }
    }

    @Test
    void headerOnlyCommentOnlyAndMissingColumnFilesAreRefusedAsAWhole() throws IOException {
        StringBuilder comments = new StringBuilder();
        for (int i = 0; i < 60; i++) {
            comments.append("# comment ").append(i).append("\n\n");
        }
        Path[] files = {write("h.csv", "t,x,y,yaw\n" + comments), write("c.tum", comments.toString()),
            write("m.csv", "t,x,y,heading\n" + csv(new SplittableRandom(6), 50, false).substring(10))};
        for (Path f : files) {
            for (int block : BLOCK_SIZES) {
                assertNotNull(assertSameOutcome(f, ReadOptions.defaults(), block), f.toString());
            }
        }
    }

    @Test
    void cutPutsEveryBlockStartJustAfterALineEnd() throws IOException {
        byte[] bytes = tum(new SplittableRandom(7), 100, true).getBytes(StandardCharsets.UTF_8);
        Path f = write("cut.tum", new String(bytes, StandardCharsets.UTF_8));
        for (int block : BLOCK_SIZES) {
            long[] starts = BlockRead.cut(ByteSource.of(f), bytes.length, block);
            assertEquals(0, starts[0]);
            assertEquals(bytes.length, starts[starts.length - 1]);
            for (int k = 1; k < starts.length - 1; k++) {
                assertEquals('\n', bytes[(int) starts[k] - 1]);
                assertTrue(starts[k] - starts[k - 1] >= Math.min(block, 1) && starts[k] > starts[k - 1]);
            }
        }
    }

    @Test
    void pairOnTwoThreadsIsReadInBlocksOnlyWhenOneFileIsAtLeastTwiceTheOther() throws IOException {
        Path small = write("s.tum", "1 0 0 0 0 0 0 1\n");
        Path half = write("h.tum", "1 0 0 0 0 0 0 1\n".repeat(2));
        Path big = write("b.tum", "1 0 0 0 0 0 0 1\n".repeat(3));
        assertEquals(ReadThreads.ONE, ReadThreads.forPair(pool, 2, big, half));
        assertTrue(ReadThreads.forPair(pool, 2, half, small) != ReadThreads.ONE);
        assertTrue(ReadThreads.forPair(pool, 2, small, big) != ReadThreads.ONE);
        assertTrue(ReadThreads.forPair(pool, 3, big, half) != ReadThreads.ONE);
        assertEquals(ReadThreads.ONE, ReadThreads.forPair(pool, 1, small, big));
        assertEquals(ReadThreads.ONE, ReadThreads.forPair(pool, 2, small, dir.resolve("missing.tum")));
    }

    @Test
    void theBiggerSecondFileIsReadOnTheCallingThread() throws IOException {
        Path small = write("s.tum", "1 0 0 0 0 0 0 1\n");
        Path big = write("b.tum", "1 0 0 0 0 0 0 1\n".repeat(3));
        assertTrue(ReadThreads.forPair(pool, 2, small, big).readSecondHere());
        assertTrue(!ReadThreads.forPair(pool, 2, big, small).readSecondHere());
        assertTrue(!ReadThreads.forPair(pool, 2, big, big).readSecondHere());
        assertTrue(!ReadThreads.ONE.readSecondHere());
    }

    @Test
    void columnsOfAFileOfMostlyBlankLinesAreSizedByThePoseLimitNotByItsLineCount() throws IOException {
        // 40 poses, then 2^21 blank lines: the sampled line length (about 1 byte) promises about 2.1
        // million poses, 134 MB of TUM columns (8 doubles a pose); the pose limit allows 100 (6.4 kB)
        Path f = write("blank.tum", tum(new SplittableRandom(8), 40, false) + "\n".repeat(1 << 21));
        ReadOptions limited = ReadOptions.defaults().withLimits(Long.MAX_VALUE, 100);
        LoadedTrajectory whole = TrajectoryReader.read(f, limited);
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        ReadThreads here = new ReadThreads(Runnable::run, 2, 1 << 16); // the helpers run in place: every block here
        long before = mx.getCurrentThreadAllocatedBytes();
        LoadedTrajectory blocks = BlockRead.read(ByteSource.of(f), f.toString(), limited,
                new TumReader.Blocks(f.toString(), limited, whole.formatReason()), here);
        long allocated = mx.getCurrentThreadAllocatedBytes() - before;
        assertNotNull(blocks, "fell back to the whole-file read");
        assertSame(whole, blocks);
        assertTrue(allocated < 16 << 20, allocated + " bytes allocated"); // 32 blocks of 64 kB, columns of 100 poses
    }

    /** Asserts the block read succeeds (not the whole-file fallback) and equals the whole-file read. */
    private static void assertSameAndInBlocks(Path f, ReadOptions options, int block,
            Function<String, BlockRead.Format> format) {
        LoadedTrajectory whole = TrajectoryReader.read(f, options);
        LoadedTrajectory blocks = BlockRead.read(ByteSource.of(f), f.toString(), options,
                format.apply(whole.formatReason()), threads(block));
        assertNotNull(blocks, "block " + block + " fell back to the whole-file read");
        assertSame(whole, blocks);
        assertSame(whole, TrajectoryReader.read(f, options, threads(block)));
    }

    /** @return the whole-file read's refusal (also the block read's), or null when both read the same poses */
    private static InputException assertSameOutcome(Path f, ReadOptions options, int block) {
        InputException wholeError = null;
        LoadedTrajectory whole = null;
        try {
            whole = TrajectoryReader.read(f, options);
        } catch (InputException e) {
            wholeError = e;
        }
        try {
            LoadedTrajectory blocks = TrajectoryReader.read(f, options, threads(block));
            assertNull(wholeError, "block " + block + " read what the whole read refused: " + wholeError);
            assertSame(whole, blocks);
        } catch (InputException e) {
            assertNotNull(wholeError, "block " + block + ": " + e.getMessage());
            assertEquals(wholeError.getMessage(), e.getMessage());
            assertEquals(wholeError.line(), e.line());
            assertEquals(wholeError.column(), e.column());
            assertEquals(wholeError.problem(), e.problem());
        }
        return wholeError;
    }

    private static void assertSame(LoadedTrajectory a, LoadedTrajectory b) {
        assertEquals(a.sha256(), b.sha256());
        assertEquals(a.format(), b.format());
        assertEquals(a.formatReason(), b.formatReason());
        Trajectory s = a.trajectory();
        Trajectory t = b.trajectory();
        assertEquals(s.size(), t.size());
        for (int i = 0; i < s.size(); i++) {
            double[] u = values(s, i);
            double[] v = values(t, i);
            for (int c = 0; c < u.length; c++) {
                assertEquals(Double.doubleToRawLongBits(u[c]), Double.doubleToRawLongBits(v[c]), "pose " + i);
            }
        }
    }

    private static double[] values(Trajectory t, int i) {
        if (t instanceof PlanarTrajectory p) {
            return new double[] {p.t(i), p.x(i), p.y(i), p.yaw(i)};
        }
        SpatialTrajectory s = (SpatialTrajectory) t;
        return new double[] {s.t(i), s.x(i), s.y(i), s.z(i), s.qw(i), s.qx(i), s.qy(i), s.qz(i)};
    }

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.UTF_8);
    }

    /** Seeded TUM lines; with {@code odd}: a byte-order mark, comments, blank and blank-only lines, CRLF, tabs, no last newline. */
    static String tum(SplittableRandom rnd, int n, boolean odd) {
        StringBuilder sb = new StringBuilder(odd ? "\uFEFF# timestamp tx ty tz qx qy qz qw\n" : "");
        double t = 1.3e9;
        for (int i = 0; i < n; i++) {
            t += 0.001 + rnd.nextDouble() * 0.05;
            double[] q = {rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5, rnd.nextDouble() - 0.5, rnd.nextDouble()};
            double norm = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            String sep = odd && i % 7 == 3 ? "\t" : " ";
            sb.append(String.format(Locale.ROOT, "%.6f", t));
            for (double v : new double[] {rnd.nextDouble() * 100 - 50, rnd.nextDouble() * 1e-3, -rnd.nextDouble() * 7}) {
                sb.append(sep).append(rnd.nextInt(3) == 0 ? String.format(Locale.ROOT, "%.3e", v) : Double.toString(v));
            }
            for (double v : q) {
                sb.append(sep).append(v / norm);
            }
            sb.append(odd ? ending(rnd, i) : "\n");
        }
        return odd ? sb.substring(0, sb.length() - (sb.charAt(sb.length() - 2) == '\r' ? 2 : 1)) : sb.toString();
    }

    /** Seeded planar CSV (an extra column at the end); {@code odd} as for {@link #tum}. */
    static String csv(SplittableRandom rnd, int n, boolean odd) {
        StringBuilder sb = new StringBuilder(odd ? "\uFEFF# made by a test\nt, x ,y,yaw,extra\n"
                : "t,x,y,yaw\n");
        double t = 12.0;
        for (int i = 0; i < n; i++) {
            t += 0.001 + rnd.nextDouble() * 0.05;
            sb.append(String.format(Locale.ROOT, "%.5f", t)).append(',').append(rnd.nextDouble() * 10 - 5)
                    .append(odd && i % 5 == 2 ? " , " : ",").append(rnd.nextLong() % 1000).append(',')
                    .append(String.format(Locale.ROOT, "%.4e", rnd.nextDouble() * 6 - 3));
            sb.append(odd ? ",x" + i + ending(rnd, i) : "\n");
        }
        return odd ? sb.substring(0, sb.length() - (sb.charAt(sb.length() - 2) == '\r' ? 2 : 1)) : sb.toString();
    }

    private static String ending(SplittableRandom rnd, int i) {
        List<String> endings = new ArrayList<>(List.of("\n", "\r\n", "\n\n", "\n# note\n", "\n \t \n", "\r\n\r\n"));
        return endings.get(i % 4 == 0 ? rnd.nextInt(endings.size()) : rnd.nextInt(2));
    }
}
