package org.trajeval.cli;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Refuses, before reading, a pair whose poses would not fit in the JVM's heap, with a message
 * naming the option that raises the heap. The pose count is estimated from the file size and the
 * mean length of the first lines; the bytes per pose are measured figures of the two evaluation
 * paths (planar CSV fast path, SE(3) general path) with a safety margin.
 */
final class MemoryBudget {
    /**
     * Planar fast path, per pose of either file (B): 4 input columns (32 B) and, per estimate pose,
     * the interpolated reference (24 B); measured 49 B per pose above the JVM's baseline at 2 x 10^7
     * poses (peak RSS), so 96 leaves a margin of about 2x.
     */
    static final long PLANAR_BYTES_PER_POSE = 96;
    /** SE(3) general path (plots, saved series): positions, 3x3 rotations, associated copies and error arrays, with margin (B). */
    static final long SPATIAL_BYTES_PER_POSE = 1200;
    /**
     * SE(3) pairs in the columnar evaluator, per pose of either file (B): the inputs as read (t,
     * x, y, z and 4 quaternion columns, 64 B) and, per estimate pose, the interpolated reference
     * (56 B) and two error arrays (16 B): at most 136 B of live data; measured 200 B per pose of
     * either file of peak RSS above the JVM's baseline (401 B per estimate pose, 10^6-pose TUM
     * pair, interpolated association, issue 15), so 240 leaves a margin of 1.2x on that and 1.8x
     * on the live data.
     */
    static final long SPATIAL_COLUMNAR_BYTES_PER_POSE = 240;

    private MemoryBudget() {
    }

    /** As {@link #check(Path, Path, long, boolean)} for the general path (every pose kept). */
    static void check(Path reference, Path estimate, long maxHeapBytes) {
        check(reference, estimate, maxHeapBytes, true);
    }

    /**
     * @param keepsEveryPose whether the general path scores the pair (plots, saved series: every
     *     associated pose and error kept), or the columnar evaluator
     */
    static void check(Path reference, Path estimate, long maxHeapBytes, boolean keepsEveryPose) {
        long poses = estimatePoses(reference) + estimatePoses(estimate);
        boolean planar = isCsv(reference) && isCsv(estimate);
        long need = poses * (planar ? PLANAR_BYTES_PER_POSE : keepsEveryPose ? SPATIAL_BYTES_PER_POSE
                : SPATIAL_COLUMNAR_BYTES_PER_POSE);
        if (need > maxHeapBytes) {
            throw new InputException(estimate.toString(), 0, null, InputProblem.TOO_LARGE, String.format(Locale.ROOT,
                    "the pair holds about %,d poses and needs about %s of memory, but the JVM may use %s;"
                            + " raise the heap (e.g. TRAJEVAL_OPTS=-Xmx%dg; with the jar: java -Xmx%4$dg -jar ...)"
                            + " or split the run into shorter spans",
                    poses, size(need), size(maxHeapBytes), (long) Math.ceil(need * 1.2 / 1073741824.0)), null);
        }
    }

    private static String size(long bytes) {
        return bytes >= (1L << 30) ? String.format(Locale.ROOT, "%.1f GiB", bytes / 1073741824.0)
                : String.format(Locale.ROOT, "%.1f MiB", bytes / 1048576.0);
    }

    private static boolean isCsv(Path p) {
        return p.getFileName() != null && p.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".csv");
    }

    /** Estimated number of lines: size / mean length of the first 64 KiB's lines; 0 when unreadable. */
    static long estimatePoses(Path p) {
        if (org.trajeval.core.io.bag.Bags.kind(p) != null) {
            return 0; // a bag's size says nothing of its poses; the bag readers bound their own memory
        }
        try {
            if (!Files.isRegularFile(p)) {
                return 0; // a pipe or device: never opened here (a FIFO would block); the reader refuses it
            }
            long size = Files.size(p);
            byte[] head = new byte[65536];
            int n;
            try (InputStream in = Files.newInputStream(p)) {
                n = in.readNBytes(head, 0, head.length);
            }
            int lines = 0;
            for (int i = 0; i < n; i++) {
                if (head[i] == '\n') {
                    lines++;
                }
            }
            if (lines == 0) {
                return 1;
            }
            return (long) (size / ((double) n / lines)) + 1;
        } catch (IOException | SecurityException e) {
            return 0; // the reader reports the problem with its own message
        }
    }
}
