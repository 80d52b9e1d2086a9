package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/**
 * Hostile files for the block read ({@link BlockRead}): seeded random damage at random places
 * (CR, NUL, multi-byte UTF-8, byte-order marks, quotes, non-finite numbers, repeated and
 * decreasing stamps, over-long lines, missing or extra fields) with small random block sizes, a
 * block that cannot be opened, an interrupted reader: the outcome is always the whole-file read's
 * (values bit for bit, hash, refusal). A file that changes while it is read: {@link BlockReadChangingFileTest}.
 */
class BlockReadHostileTest extends ReadPoolFixture {

    @TempDir
    Path dir;

    @Test
    void randomlyDamagedTumAndCsvFilesGiveTheWholeFileReadsOutcomeAtRandomBlockSizes() throws IOException {
        SplittableRandom rnd = new SplittableRandom(1010);
        int inBlocks = 0;
        int refused = 0;
        for (int k = 0; k < 240; k++) {
            boolean tum = k % 2 == 0;
            String clean = tum ? BlockReadTest.tum(rnd, 40 + rnd.nextInt(60), rnd.nextBoolean())
                    : BlockReadTest.csv(rnd, 40 + rnd.nextInt(60), rnd.nextBoolean());
            byte[] bytes = damage(rnd, clean.getBytes(StandardCharsets.UTF_8), k % 6 == 0 ? 0 : 1 + rnd.nextInt(2));
            Path f = Files.write(dir.resolve("r" + k + (tum ? ".tum" : ".csv")), bytes);
            ReadOptions options = rnd.nextInt(4) == 0 ? ReadOptions.defaults().withDuplicates(DuplicateTimestamps.KEEP)
                    : ReadOptions.defaults();
            for (int b = 0; b < 3; b++) {
                int block = 1 + rnd.nextInt(b == 0 ? 8 : 400);
                if (assertSameOutcome(f, options, block) != null) {
                    refused++;
                } else if (BlockRead.read(ByteSource.of(f), f.toString(), options, format(f, options),
                        threads(block)) != null) {
                    inBlocks++;
                }
            }
        }
        assertTrue(inBlocks > 100 && refused > 100, "in blocks " + inBlocks + ", refused " + refused);
    }

    @Test
    void crlfFileAndEveryDecreasingOrRepeatedStampGiveTheWholeFileReadsOutcomeWithTheEdgeAtEveryByte()
            throws IOException {
        String crlf = BlockReadTest.tum(new SplittableRandom(21), 12, false).replace("\n", "\r\n");
        Path f = Files.writeString(dir.resolve("crlf.tum"), crlf);
        for (int block = 1; block <= 120; block++) { // the nominal edge falls on every byte of the first lines
            assertNull(assertSameOutcome(f, ReadOptions.defaults(), block));
        }
        String[] lines = BlockReadTest.tum(new SplittableRandom(22), 12, false).split("\n", -1);
        ReadOptions keep = ReadOptions.defaults().withDuplicates(DuplicateTimestamps.KEEP);
        for (int at = 1; at < 12; at++) {
            for (int back = 1; back <= Math.min(2, at); back++) {
                String[] copy = lines.clone();
                copy[at] = copy[at - back].substring(0, stampEnd(copy[at - back])) + copy[at].substring(
                        stampEnd(copy[at]));
                Path g = Files.writeString(dir.resolve("stamp" + at + "_" + back + ".tum"), String.join("\n", copy));
                for (int block = 1; block <= 90; block += 3) {
                    assertNotNull(assertSameOutcome(g, ReadOptions.defaults(), block));
                    assertEquals(back == 1, assertSameOutcome(g, keep, block) == null);
                }
            }
        }
    }

    @Test
    void emptyBomOnlyHeaderOnlyAndNewlineOnlyFilesAreRefusedAsAWhole() throws IOException {
        String[] texts = {"", "\uFEFF", "\uFEFF\n", "\n".repeat(50), "\r\n".repeat(40), "t,x,y,yaw",
            "t,x,y,yaw\n", "t,x,y,yaw\r\n" + "\r\n".repeat(30), "# only\n".repeat(30), "\0".repeat(100)};
        int k = 0;
        for (String text : texts) {
            for (String ext : new String[] {".csv", ".tum"}) {
                Path f = Files.writeString(dir.resolve("e" + k++ + ext), text);
                for (int block = 1; block < 12; block++) {
                    assertNotNull(assertSameOutcome(f, ReadOptions.defaults(), block), f + " " + block);
                }
            }
        }
    }

    @Test
    void quotesOnlyInAnUnusedColumnOrAfterTheFirstBlockAndOtherDelimitersReadAsTheWholeFile() throws IOException {
        String data = BlockReadTest.csv(new SplittableRandom(20), 120, false);
        String body = data.substring(data.indexOf('\n') + 1);
        String[] lines = body.split("\n", -1);
        String[] quoted = lines.clone();
        quoted[70] = quoted[70] + ",\"a, \"\"b\"\"\nstill the note\"";
        String[] texts = {"t,x,y,yaw,\"note\"\n" + body, "t,x,y,yaw,note\n" + String.join("\n", quoted),
            "t,x,y,yaw\n" + body.replace(",", ";"), "t\tx\ty\tyaw\n" + body.replace(",", "\t")};
        ReadOptions[] options = {ReadOptions.defaults(), ReadOptions.defaults(),
            ReadOptions.defaults().withCsv(new CsvLayout("t", "x", "y", "yaw", ';', TimeUnit.S)),
            ReadOptions.defaults().withCsv(new CsvLayout("t", "x", "y", "yaw", '\t', TimeUnit.MS))};
        texts[2] = texts[2].replace("t,x,y,yaw", "t;x;y;yaw");
        for (int k = 0; k < texts.length; k++) {
            Path f = Files.writeString(dir.resolve("q" + k + ".csv"), texts[k]);
            for (int block : new int[] {1, 30, 97, 500, 1500}) {
                assertSameOutcome(f, options[k], block);
            }
        }
    }

    @Test
    void lineLongerThanEveryBlockAndHeaderLongerThanABlockReadAsTheWholeFile() throws IOException {
        String data = BlockReadTest.csv(new SplittableRandom(11), 80, false);
        String longHeader = "t,x,y,yaw," + "c".repeat(3000) + "\n" + data.substring(data.indexOf('\n') + 1);
        String[] lines = data.split("\n", -1);
        lines[40] = lines[40] + "," + "9".repeat(5000);
        Path a = Files.writeString(dir.resolve("longhead.csv"), longHeader);
        Path b = Files.writeString(dir.resolve("longline.csv"), String.join("\n", lines));
        String tum = BlockReadTest.tum(new SplittableRandom(12), 80, false);
        Path c = Files.writeString(dir.resolve("longcomment.tum"), tum.substring(0, 500) + "\n#" + "x".repeat(4000)
                + "\n" + tum.substring(500));
        for (Path f : new Path[] {a, b, c}) {
            for (int block : new int[] {1, 50, 999, 2999, 3001, 4100}) {
                assertSameOutcome(f, ReadOptions.defaults(), block);
            }
        }
    }

    @Test
    void moreThanThePoseLimitOrByteLimitIsRefusedAsTheWholeFileRefusesIt() throws IOException {
        Path f = Files.writeString(dir.resolve("lim.tum"), BlockReadTest.tum(new SplittableRandom(13), 200, false));
        long size = Files.size(f);
        for (ReadOptions o : new ReadOptions[] {ReadOptions.defaults().withLimits(size, 199),
            ReadOptions.defaults().withLimits(size - 1, 200), ReadOptions.defaults().withLimits(size, 1)}) {
            for (int block : new int[] {1, 64, 500, 4000}) {
                assertNotNull(assertSameOutcome(f, o, block));
            }
        }
        for (int block : new int[] {1, 64, 500}) {
            assertNull(assertSameOutcome(f, ReadOptions.defaults().withLimits(size, 200), block));
        }
    }

    @Test
    void blockThatCannotBeOpenedFallsBackWithoutHangingAndThePoolStaysUsable() throws IOException {
        Path f = Files.writeString(dir.resolve("fail.tum"), BlockReadTest.tum(new SplittableRandom(17), 300, false));
        ByteSource failing = new FileSourceDouble(f) {
            @Override
            public InputStream open(long from) throws IOException {
                if (from > 0 && from < 4000) {
                    throw new IOException("injected failure at " + from);
                }
                return super.open(from);
            }
        };
        ReadThreads threads = threads(300);
        for (int i = 0; i < 5; i++) {
            assertNull(tumInBlocks(failing, f, threads));
        }
        assertSameOutcome(f, ReadOptions.defaults(), 300);
        assertEquals(300, tumInBlocks(ByteSource.of(f), f, threads).trajectory().size());
    }

    @Test
    void interruptedReaderGetsTheWholeFileReadsOutcomeAndKeepsItsInterrupt() throws Exception {
        Path f = Files.writeString(dir.resolve("int.tum"), BlockReadTest.tum(new SplittableRandom(18), 300, false));
        String whole;
        Thread.currentThread().interrupt();
        try {
            whole = outcome(() -> TrajectoryReader.read(f, ReadOptions.defaults()));
        } finally {
            assertTrue(Thread.interrupted());
        }
        for (int block : new int[] {1, 200, 3000}) {
            Thread.currentThread().interrupt();
            String blocks;
            try {
                blocks = outcome(() -> TrajectoryReader.read(f, ReadOptions.defaults(), threads(block)));
            } finally {
                assertTrue(Thread.interrupted(), "the interrupt is kept");
            }
            assertEquals(whole, blocks);
        }
        ExecutorService own = Executors.newFixedThreadPool(2);
        own.shutdownNow();
        assertTrue(own.awaitTermination(10, java.util.concurrent.TimeUnit.SECONDS));
        ReadThreads rejected = new ReadThreads(own, 3, 200); // helpers refused: the caller reads every block
        assertFalse(outcome(() -> TrajectoryReader.read(f, ReadOptions.defaults(), rejected)).startsWith("refused"));
        assertEquals(outcome(() -> TrajectoryReader.read(f, ReadOptions.defaults())),
                outcome(() -> TrajectoryReader.read(f, ReadOptions.defaults(), rejected)));
    }

    /** A TUM file read in blocks from {@code source}, with the default options. */
    static LoadedTrajectory tumInBlocks(ByteSource source, Path f, ReadThreads threads) {
        return BlockRead.read(source, f.toString(), ReadOptions.defaults(),
                new TumReader.Blocks(f.toString(), ReadOptions.defaults(), ""), threads);
    }

    private static BlockRead.Format format(Path f, ReadOptions o) {
        return f.toString().endsWith(".tum") ? new TumReader.Blocks(f.toString(), o, "")
                : new CsvTrajectoryReader.Blocks(f.toString(), o, "");
    }

    /** @return the whole-file read's refusal (also the block read's), or null when both read the same poses */
    private static InputException assertSameOutcome(Path f, ReadOptions options, int block) {
        InputException wholeError = null;
        String whole = null;
        try {
            whole = describe(TrajectoryReader.read(f, options));
        } catch (InputException e) {
            wholeError = e;
        }
        try {
            String blocks = describe(TrajectoryReader.read(f, options, threads(block)));
            assertNull(wholeError, f + " block " + block + " read what the whole read refused: " + wholeError);
            assertEquals(whole, blocks, f + " block " + block);
        } catch (InputException e) {
            assertNotNull(wholeError, f + " block " + block + ": " + e.getMessage());
            assertEquals(wholeError.getMessage(), e.getMessage(), f + " block " + block);
            assertEquals(wholeError.line(), e.line());
            assertEquals(wholeError.column(), e.column());
            assertEquals(wholeError.problem(), e.problem());
        }
        return wholeError;
    }

    private interface Read {
        LoadedTrajectory read();
    }

    private static String outcome(Read r) {
        try {
            return describe(r.read());
        } catch (InputException e) {
            return "refused " + e.problem() + " " + e.line() + " " + e.column() + " " + e.getMessage();
        }
    }

    /** @return every value's bits, the hash, format and reason, as text */
    private static String describe(LoadedTrajectory t) {
        return t.sha256() + " " + t.format() + " " + t.formatReason() + "\n" + describe(t.trajectory());
    }

    /** @return every value's bits, pose by pose, as text */
    static String describe(Trajectory t) {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < t.size(); i++) {
            double[] v;
            if (t instanceof PlanarTrajectory p) {
                v = new double[] {p.t(i), p.x(i), p.y(i), p.yaw(i)};
            } else {
                SpatialTrajectory s = (SpatialTrajectory) t;
                v = new double[] {s.t(i), s.x(i), s.y(i), s.z(i), s.qw(i), s.qx(i), s.qy(i), s.qz(i)};
            }
            for (double x : v) {
                sb.append(Long.toHexString(Double.doubleToRawLongBits(x))).append(' ');
            }
            sb.append('\n');
        }
        return sb.toString();
    }

    /** Damage at random places: each a snippet inserted at a random byte, or a line's stamp repeated or lowered. */
    private static byte[] damage(SplittableRandom rnd, byte[] clean, int times) {
        byte[][] snippets = {"\r".getBytes(StandardCharsets.UTF_8), {0}, "é".getBytes(StandardCharsets.UTF_8),
            "\uFEFF".getBytes(StandardCharsets.UTF_8), "\"".getBytes(StandardCharsets.UTF_8),
            "\nnan 0 0 0 0 0 0 1\n".getBytes(StandardCharsets.UTF_8), " inf".getBytes(StandardCharsets.UTF_8),
            "\n# c\n\n".getBytes(StandardCharsets.UTF_8), "\n".getBytes(StandardCharsets.UTF_8),
            ",".getBytes(StandardCharsets.UTF_8), " 1e999".getBytes(StandardCharsets.UTF_8),
            "\r\n".getBytes(StandardCharsets.UTF_8), "\n9".getBytes(StandardCharsets.UTF_8),
            {(byte) 0xC3}, "\n\uFEFF".getBytes(StandardCharsets.UTF_8)};
        byte[] b = clean;
        for (int i = 0; i < times; i++) {
            if (rnd.nextInt(3) == 0) {
                b = restamp(rnd, b);
                continue;
            }
            byte[] s = snippets[rnd.nextInt(snippets.length)];
            int at = rnd.nextInt(b.length + 1);
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            out.write(b, 0, at);
            out.write(s, 0, s.length);
            out.write(b, at, b.length - at);
            b = out.toByteArray();
        }
        return b;
    }

    /** Gives a random line the stamp of the line before it, or of the line two before. */
    private static byte[] restamp(SplittableRandom rnd, byte[] b) {
        String[] lines = new String(b, StandardCharsets.UTF_8).split("\n", -1);
        List<Integer> data = new ArrayList<>();
        for (int i = 0; i < lines.length; i++) {
            if (!lines[i].isBlank() && Character.isDigit(lines[i].charAt(0))) {
                data.add(i);
            }
        }
        if (data.size() < 4) {
            return b;
        }
        int j = 2 + rnd.nextInt(data.size() - 2);
        String from = lines[data.get(j - 1 - rnd.nextInt(2))];
        String to = lines[data.get(j)];
        int fe = stampEnd(from);
        int te = stampEnd(to);
        lines[data.get(j)] = from.substring(0, fe) + to.substring(te);
        return String.join("\n", lines).getBytes(StandardCharsets.UTF_8);
    }

    private static int stampEnd(String line) {
        int i = 0;
        while (i < line.length() && line.charAt(i) != ',' && line.charAt(i) != ' ' && line.charAt(i) != '\t') {
            i++;
        }
        return i;
    }
}
