package org.trajeval.core.io;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Not a test: times the read path of one file held in memory ({@link InputBytes}, so no disk I/O),
 * {@code runs} times in one JVM, and prints the minimum thread CPU time. Usage:
 * {@code java -cp ... org.trajeval.core.io.ParseSpeed FILE RUNS [hash|parse|read] [fields]}:
 * {@code hash} reads the blocks and hashes them ({@link ByteLines}), {@code parse} also splits and
 * scans every number ({@link NumericRows}, every field selected), {@code read} is the whole
 * {@link TrajectoryReader#read(InputBytes, ReadOptions)}. Parse cost per number = (parse - hash) /
 * numbers. A {@code .csv} file is read as a planar CSV with a header (4 fields), anything else as
 * TUM (8 fields).
 */
public final class ParseSpeed {
    public static void main(String[] args) throws Exception {
        Path file = Path.of(args[0]);
        int runs = Integer.parseInt(args[1]);
        String mode = args.length > 2 ? args[2] : "parse";
        boolean tum = !file.toString().endsWith(".csv");
        int fields = args.length > 3 ? Integer.parseInt(args[3]) : tum ? 8 : 4;
        InputBytes bytes = InputBytes.read(file.toString(), () -> Files.newInputStream(file), Long.MAX_VALUE);
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        double best = 1e9;
        long lines = 0;
        for (int run = 0; run < runs; run++) {
            long c0 = mx.getCurrentThreadCpuTime();
            double sum = 0;
            lines = 0;
            if (mode.equals("read")) {
                sum = TrajectoryReader.read(bytes, ReadOptions.defaults()).trajectory().size();
                lines = (long) sum;
            } else {
                try (ByteLines bl = ByteLines.open(bytes, "x", Long.MAX_VALUE)) {
                    if (mode.equals("parse")) {
                        ReadPathSpeed.Scanned scanned = ReadPathSpeed.scanEveryField(bl, "x", tum, fields);
                        lines = scanned.lines();
                        sum = scanned.checksum();
                    }
                    bl.finishSha256();
                }
            }
            double cpu = (mx.getCurrentThreadCpuTime() - c0) * 1e-9;
            best = Math.min(best, cpu);
            if (runs <= 30) {
                System.out.printf(Locale.ROOT, "%s cpu %.4f s (%d, %.6g)%n", mode, cpu, lines, sum);
            }
        }
        System.out.printf(Locale.ROOT, "%s best %.4f s, %.2f ns/number%n", mode, best, best * 1e9 / (lines * fields));
    }
}
