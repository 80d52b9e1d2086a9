package org.trajeval.core.io;

import java.io.BufferedWriter;
import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.SplittableRandom;

/**
 * Not a test: measures the planar CSV fast path (rows/s) and the bytes allocated per parsed line.
 * Usage: {@code java ... org.trajeval.core.io.CsvReadSpeed <file.csv> [rows]} - writes a seeded
 * random file of that many rows (default 10^7) if it does not exist, then reads it 5 times.
 */
public final class CsvReadSpeed {
    private CsvReadSpeed() {
    }

    public static void main(String[] args) throws IOException {
        Path file = Path.of(args[0]);
        int rows = args.length > 1 ? Integer.parseInt(args[1]) : 10_000_000;
        if (!Files.exists(file)) {
            if (args.length > 2 && args[2].equals("shortest")) {
                writeShortest(file, rows);
            } else {
                write(file, rows);
            }
        }
        System.out.printf(Locale.ROOT, "%s: %d bytes%n", file, Files.size(file));
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long tid = Thread.currentThread().getId();
        for (int run = 0; run < 5; run++) {
            long t0 = System.nanoTime();
            LoadedTrajectory t = TrajectoryReader.read(file, ReadOptions.defaults());
            double s = (System.nanoTime() - t0) * 1e-9;
            System.out.printf(Locale.ROOT, "read: %d rows in %.3f s = %.2f M rows/s (%s, sha %s...)%n",
                    t.trajectory().size(), s, t.trajectory().size() / s / 1e6, t.formatReason(), t.sha256().substring(0, 8));
        }
        // parse-only loop: allocation per line, without the growing columns
        for (int run = 0; run < 3; run++) {
            long a0 = mx.getThreadAllocatedBytes(tid);
            long t0 = System.nanoTime();
            long n = 0;
            try (ByteLines lines = ByteLines.open(file, file.toString(), Long.MAX_VALUE)) {
                NumericRows r = new NumericRows(lines, file.toString(), (byte) ',', true);
                r.nextContentLine();
                r.select(new int[] {0, 1, 2, 3}, new String[] {"t", "x", "y", "yaw"}, new String[] {"", "", "", ""});
                r.requireFields(4, "t,x,y,yaw");
                double[] row = new double[4];
                double sum = 0;
                while (r.next(row)) {
                    sum += row[1];
                    n++;
                }
                lines.finishSha256();
                if (sum == 42) {
                    System.out.println();
                }
            }
            double s = (System.nanoTime() - t0) * 1e-9;
            long bytes = mx.getThreadAllocatedBytes(tid) - a0;
            System.out.printf(Locale.ROOT, "parse only: %.2f M rows/s, %d bytes allocated in all = %.4f bytes/line%n",
                    n / s / 1e6, bytes, (double) bytes / n);
        }
    }

    /** Same walk, written by {@link TrajectoryWriter} (shortest round-trip digits, about 17 per number). */
    private static void writeShortest(Path file, int rows) throws IOException {
        SplittableRandom rnd = new SplittableRandom(20240611L);
        double[] t = new double[rows];
        double[] x = new double[rows];
        double[] y = new double[rows];
        double[] yaw = new double[rows];
        double heading = 0;
        for (int i = 0; i < rows; i++) {
            heading += rnd.nextDouble(-0.01, 0.01);
            t[i] = 1.7e9 + 0.01 * (i + 1);
            x[i] = (i == 0 ? 0 : x[i - 1]) + 0.05 * Math.cos(heading);
            y[i] = (i == 0 ? 0 : y[i - 1]) + 0.05 * Math.sin(heading);
            yaw[i] = heading;
        }
        TrajectoryWriter.write(org.trajeval.core.traj.PlanarTrajectory.of(t, x, y, yaw), file);
    }

    private static void write(Path file, int rows) throws IOException {
        SplittableRandom rnd = new SplittableRandom(20240611L);
        double t = 1.7e9;
        double x = 0;
        double y = 0;
        double yaw = 0;
        try (BufferedWriter w = Files.newBufferedWriter(file, StandardCharsets.US_ASCII)) {
            w.write("t,x,y,yaw\n");
            StringBuilder sb = new StringBuilder();
            for (int i = 0; i < rows; i++) {
                t += 0.01;
                yaw += rnd.nextDouble(-0.01, 0.01);
                x += 0.05 * Math.cos(yaw);
                y += 0.05 * Math.sin(yaw);
                sb.setLength(0);
                sb.append(String.format(Locale.ROOT, "%.6f,%.6f,%.6f,%.6f%n", t, x, y, yaw));
                w.append(sb);
            }
        }
    }
}
