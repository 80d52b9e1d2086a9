package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class ByteLinesTest {
    @Test
    void linesSpanningBlockBoundariesAndLongerThanABlockComeOutWhole(@TempDir Path dir) throws IOException {
        SplittableRandom rnd = new SplittableRandom(1);
        List<String> expected = new ArrayList<>();
        StringBuilder all = new StringBuilder();
        for (int i = 0; i < 3000; i++) {
            int len = i == 1500 ? 3 * ByteLines.BLOCK_BYTES : rnd.nextInt(2000);
            StringBuilder line = new StringBuilder(len);
            for (int k = 0; k < len; k++) {
                line.append((char) ('a' + rnd.nextInt(26)));
            }
            expected.add(line.toString());
            all.append(line).append(rnd.nextBoolean() ? "\r\n" : "\n");
        }
        Path file = Files.writeString(dir.resolve("lines.txt"), all);
        try (ByteLines lines = ByteLines.open(file, "lines.txt", Long.MAX_VALUE)) {
            for (int i = 0; i < expected.size(); i++) {
                assertTrue(lines.next());
                assertEquals(i + 1, lines.lineNumber());
                assertEquals(expected.get(i), new String(lines.buffer(), lines.start(), lines.end() - lines.start(),
                        StandardCharsets.US_ASCII), "line " + (i + 1));
            }
            assertFalse(lines.next());
            assertEquals(RefdataReadingTest.sha256(file), lines.finishSha256());
        }
    }

    @Test
    void aFileWithinOneBlockIsSampledFromMemoryAsTheFileItselfIsSampled(@TempDir Path dir) throws IOException {
        // 700 kB of lines growing from 10 to about 60 bytes: more than the sampled stretches, less than a block
        Path file = Files.writeString(dir.resolve("within.txt"), growingLines(700_000));
        double fromFile = ByteLines.sampleLineLength(ByteSource.of(file), Files.size(file));
        int[] sampledReads = {0};
        ByteSource counted = new ByteSource() {
            private final ByteSource local = ByteSource.of(file);

            @Override
            public java.io.InputStream open() throws IOException {
                return local.open();
            }

            @Override
            public long size() throws IOException {
                return local.size();
            }

            @Override
            public String fileName() {
                return local.fileName();
            }

            @Override
            public int readAt(long position, java.nio.ByteBuffer dst) throws IOException {
                sampledReads[0]++;
                return local.readAt(position, dst);
            }
        };
        try (ByteLines lines = ByteLines.open(counted, "within.txt", Long.MAX_VALUE)) {
            assertTrue(lines.next());
            assertTrue(fromFile > 10 && fromFile < 70, "sampled " + fromFile);
            assertEquals(fromFile, lines.sampledBytesPerLine());
            assertEquals(0, sampledReads[0], "reads of the file to sample it");
        }
    }

    @Test
    void aFileBeyondOneBlockIsSampledFromTheFileWhenFirstAsked(@TempDir Path dir) throws IOException {
        Path file = Files.writeString(dir.resolve("beyond.txt"), growingLines(3 * ByteLines.BLOCK_BYTES));
        double fromFile = ByteLines.sampleLineLength(ByteSource.of(file), Files.size(file));
        try (ByteLines lines = ByteLines.open(file, "beyond.txt", Long.MAX_VALUE)) {
            while (lines.next()) {
                // the buffer now holds only the file's last block
            }
            assertTrue(fromFile > 10, "sampled " + fromFile);
            assertEquals(fromFile, lines.sampledBytesPerLine());
        }
    }

    @Test
    void linesOfOneLengthAreSampledAtExactlyThatLength(@TempDir Path dir) throws IOException {
        // every line 36 characters and '\n': between a stretch's first and last '\n' lie whole lines of 37 bytes
        String line = "0123456789 0123456789 0123456789 abc\n";
        Path file = Files.writeString(dir.resolve("even.txt"), line.repeat(20_000));
        assertEquals(37.0, ByteLines.sampleLineLength(ByteSource.of(file), Files.size(file)));
        try (ByteLines lines = ByteLines.open(file, "even.txt", Long.MAX_VALUE)) {
            assertTrue(lines.next());
            assertEquals(37.0, lines.sampledBytesPerLine());
        }
    }

    @Test
    void newlinesAreCountedAsOneByOneAtEveryOffsetAndNextToEveryByte() {
        SplittableRandom rnd = new SplittableRandom(7);
        for (int round = 0; round < 2000; round++) {
            byte[] b = new byte[1 + rnd.nextInt(80)];
            for (int i = 0; i < b.length; i++) {
                // '\n' often, and every other byte value (0x0B and 0x8A among them) now and then
                b[i] = rnd.nextInt(3) == 0 ? (byte) '\n' : (byte) rnd.nextInt(256);
            }
            int from = rnd.nextInt(b.length);
            int to = from + rnd.nextInt(b.length - from + 1);
            int expected = 0;
            for (int i = from; i < to; i++) {
                expected += b[i] == '\n' ? 1 : 0;
            }
            assertEquals(expected, ByteLines.countNewlines(b, from, to), "round " + round);
        }
    }

    /** @return lines of about {@code bytes} bytes in all, longer and longer (10 to about 60 bytes) */
    private static String growingLines(int bytes) {
        StringBuilder all = new StringBuilder();
        for (int i = 0; all.length() < bytes; i++) {
            all.append("x".repeat(9 + (int) (50L * all.length() / bytes) + i % 3)).append('\n');
        }
        return all.toString();
    }

    @Test
    void newlineSearchFindsTheFirstNewlineAtEveryOffset() {
        for (int len = 0; len < 40; len++) {
            for (int at = 0; at <= len; at++) {
                byte[] b = new byte[len];
                java.util.Arrays.fill(b, (byte) 'x');
                if (at < len) {
                    b[at] = '\n';
                }
                // a byte just above '\n' (0x0B) and below (0x09) must not be mistaken for it
                if (at + 1 < len) {
                    b[at + 1] = 0x0B;
                }
                assertEquals(at < len ? at : -1, ByteLines.indexOfNewline(b, 0, len), "len " + len + " at " + at);
            }
        }
    }
}
