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
