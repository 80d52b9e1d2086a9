package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The column size guessed from the first lines must not leave the columns much longer than the file. */
class PoseBufferSizingTest {
    @TempDir
    Path dir;

    @Test
    void columnsSizedFromShortFirstLinesAreTrimmedToWithinFourPercent() throws IOException {
        // 2 000 short lines (8 to 11 bytes) then 60 000 long ones (40 bytes): the guess taken after the
        // first 1 024 lines expects about 4x too many poses
        StringBuilder sb = new StringBuilder();
        int n = 62_000;
        for (int i = 0; i < n; i++) {
            sb.append(i < 2_000 ? String.format("%d,1,2,3%n", i)
                    : String.format("%d.123456,1.1234567,2.1234567,3.12345%n", i));
        }
        Path file = dir.resolve("growing.csv");
        Files.writeString(file, sb, StandardCharsets.US_ASCII);
        try (ByteLines lines = ByteLines.open(file, "growing.csv", Long.MAX_VALUE)) {
            NumericRows rows = new NumericRows(lines, "growing.csv", (byte) ',', true);
            rows.select(new int[] {0, 1, 2, 3}, new String[] {"t", "x", "y", "yaw"}, new String[] {"", "", "", ""});
            rows.requireFields(4, "t,x,y,yaw");
            PoseBuffer poses = new PoseBuffer("growing.csv", "t", 4, TimestampOrder.REFUSE_UNSORTED,
                    DuplicateTimestamps.KEEP, Long.MAX_VALUE);
            poses.sizeFrom(lines);
            double[] row = new double[4];
            while (rows.next(row)) {
                assertEquals(PoseBuffer.ACCEPTED, poses.add(row, rows.lineNumber()));
            }
            double[][] columns = poses.finishUntrimmed("nothing");
            assertEquals(n, poses.size());
            for (double[] column : columns) {
                assertTrue(column.length >= n && column.length <= n + n / 25,
                        "column of " + column.length + " for " + n + " poses");
            }
            assertEquals(61_999.123456, columns[0][n - 1]);
            assertEquals(3.12345, columns[3][n - 1]);
        }
    }

    @Test
    void aBufferGivenItsPoseCountHandsOverItsOwnColumns() {
        // capacity(3) and three poses: finish returns the buffer's columns themselves (the same
        // arrays on every call), three values long; without it they are trimmed copies of longer ones
        PoseBuffer sized = new PoseBuffer("t.txt", "t", 2, TimestampOrder.REFUSE_UNSORTED, Long.MAX_VALUE).capacity(3);
        PoseBuffer grown = new PoseBuffer("t.txt", "t", 2, TimestampOrder.REFUSE_UNSORTED, Long.MAX_VALUE);
        for (int i = 0; i < 3; i++) {
            assertEquals(PoseBuffer.ACCEPTED, sized.add(new double[] {i, 10 * i}, i + 1));
            assertEquals(PoseBuffer.ACCEPTED, grown.add(new double[] {i, 10 * i}, i + 1));
        }
        double[][] first = sized.finish("nothing");
        double[][] again = sized.finish("nothing");
        assertArrayEquals(new double[] {0, 10, 20}, first[1], 0.0);
        assertEquals(3, first[0].length);
        assertSame(first[0], again[0]);
        assertSame(first[1], again[1]);
        assertNotSame(grown.finish("nothing")[1], grown.finish("nothing")[1]);
    }
}
