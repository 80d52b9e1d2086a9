package org.trajeval.core.io;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Not a test: splits the read of one file held in memory ({@link InputBytes}, no disk I/O) into
 * its stages, {@code runs} times in one JVM, and prints the minimum thread CPU time of each. Usage:
 * {@code java -cp ... org.trajeval.core.io.ReadStageSpeed FILE RUNS}. Stages: {@code hash} (the
 * blocks read and hashed, {@link ByteLines}), {@code hash+parse} (also every number split and
 * scanned, {@link ReadPathSpeed#scanEveryField}), {@code read} (the whole
 * {@link TrajectoryReader#read(InputBytes, ReadOptions)}: also the checks, the column stores and
 * the trajectory's own checks) and {@code alloc} (as many zeroed columns as the reader fills, the
 * page faults and zeroing that {@code read} pays for its columns). Per line beyond parsing =
 * (read - hash+parse - alloc) / lines. A {@code .csv} file is read as a planar CSV (4 fields),
 * anything else as TUM (8 fields).
 */
public final class ReadStageSpeed {
    private ReadStageSpeed() {
    }

    public static void main(String[] args) throws Exception {
        Path file = Path.of(args[0]);
        int runs = Integer.parseInt(args[1]);
        boolean tum = !file.toString().endsWith(".csv");
        int fields = tum ? 8 : 4;
        InputBytes bytes = InputBytes.read(file.toString(), () -> Files.newInputStream(file), Long.MAX_VALUE);
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        double hash = 1e9;
        double parse = 1e9;
        double read = 1e9;
        double alloc = 1e9;
        long lines = 0;
        Object kept;
        for (int run = 0; run < runs; run++) {
            kept = null;
            long c0 = mx.getCurrentThreadCpuTime();
            try (ByteLines bl = ByteLines.open(bytes, "x", Long.MAX_VALUE)) {
                bl.finishSha256();
            }
            long c1 = mx.getCurrentThreadCpuTime();
            try (ByteLines bl = ByteLines.open(bytes, "x", Long.MAX_VALUE)) {
                lines = ReadPathSpeed.scanEveryField(bl, "x", tum, fields).lines();
                bl.finishSha256();
            }
            long c2 = mx.getCurrentThreadCpuTime();
            kept = TrajectoryReader.read(bytes, ReadOptions.defaults());
            long c3 = mx.getCurrentThreadCpuTime();
            kept = null;
            double[][] columns = new double[fields][(int) lines];
            long c4 = mx.getCurrentThreadCpuTime();
            kept = columns;
            hash = Math.min(hash, (c1 - c0) * 1e-9);
            parse = Math.min(parse, (c2 - c1) * 1e-9);
            read = Math.min(read, (c3 - c2) * 1e-9);
            alloc = Math.min(alloc, (c4 - c3) * 1e-9);
        }
        System.out.printf(Locale.ROOT,
                "min of %d: hash %.4f s, hash+parse %.4f s, read %.4f s, alloc %.4f s | parse %.2f ns/number,"
                        + " read beyond parse and alloc %.2f ns/line%n",
                runs, hash, parse, read, alloc, (parse - hash) * 1e9 / (lines * fields),
                (read - parse - alloc) * 1e9 / lines);
    }
}
