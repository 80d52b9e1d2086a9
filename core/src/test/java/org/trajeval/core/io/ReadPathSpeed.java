package org.trajeval.core.io;

import java.io.IOException;
import java.io.InputStream;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.util.Locale;

/**
 * Not a test: times the read path of one trajectory file stage by stage, in one JVM, so that the
 * cost of each stage is the difference of two rows. Usage:
 * {@code java -cp ... org.trajeval.core.io.ReadPathSpeed FILE [runs] [fields]} (fields: 4 for a
 * planar CSV {@code t,x,y,yaw} with a header, 8 for TUM; guessed from the extension).
 *
 * <p>Stages: {@code bytes} (the file read in 1 MiB blocks, nothing else), {@code sha256} (read and
 * hash), {@code lines} ({@link ByteLines}: read, hash, find every line end), {@code numbers}
 * ({@link NumericRows}: also split and scan every field), {@code read} (the whole
 * {@link TrajectoryReader#read}: detection, checks, columns). Each prints the thread's CPU time,
 * MB/s and ns per number.
 */
public final class ReadPathSpeed {
    private ReadPathSpeed() {
    }

    public static void main(String[] args) throws IOException {
        Path file = Path.of(args[0]);
        int runs = args.length > 1 ? Integer.parseInt(args[1]) : 5;
        boolean tum = file.toString().endsWith(".tum") || file.toString().endsWith(".txt");
        int fields = args.length > 2 ? Integer.parseInt(args[2]) : tum ? 8 : 4;
        long size = Files.size(file);
        long[] lineCount = {0};
        System.out.printf(Locale.ROOT, "%s: %d bytes, %d fields per line%n", file, size, fields);
        for (int run = 0; run < runs; run++) {
            time("bytes", size, 0, () -> {
                byte[] buf = new byte[ByteLines.BLOCK_BYTES];
                long s = 0;
                try (InputStream in = Files.newInputStream(file)) {
                    int n;
                    while ((n = in.read(buf)) > 0) {
                        s += buf[n - 1];
                    }
                }
                return s;
            });
            time("sha256", size, 0, () -> {
                byte[] buf = new byte[ByteLines.BLOCK_BYTES];
                MessageDigest sha = ByteLines.sha256();
                try (InputStream in = Files.newInputStream(file)) {
                    int n;
                    while ((n = in.read(buf)) > 0) {
                        sha.update(buf, 0, n);
                    }
                }
                return sha.digest()[0];
            });
            time("lines", size, 0, () -> {
                long n = 0;
                try (ByteLines lines = ByteLines.open(file, file.toString(), Long.MAX_VALUE)) {
                    while (lines.next()) {
                        n++;
                    }
                    lines.finishSha256();
                }
                lineCount[0] = n;
                return n;
            });
            long numbers = lineCount[0] * fields;
            time("numbers", size, numbers, () -> {
                try (ByteLines lines = ByteLines.open(file, file.toString(), Long.MAX_VALUE)) {
                    Scanned scanned = scanEveryField(lines, file.toString(), tum, fields);
                    lines.finishSha256();
                    return (long) scanned.checksum();
                }
            });
            time("read", size, numbers, () -> TrajectoryReader.read(file, ReadOptions.defaults()).trajectory().size());
        }
    }

    private interface Stage {
        long run() throws IOException;
    }

    private static void time(String name, long bytes, long numbers, Stage stage) throws IOException {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long c0 = mx.getCurrentThreadCpuTime();
        long t0 = System.nanoTime();
        long r = stage.run();
        double wall = (System.nanoTime() - t0) * 1e-9;
        double cpu = (mx.getCurrentThreadCpuTime() - c0) * 1e-9;
        System.out.printf(Locale.ROOT, "%-8s wall %7.3f s  cpu %7.3f s  %7.1f MB/s%s  (%d)%n", name, wall, cpu,
                bytes / cpu / 1e6, numbers > 0 ? String.format(Locale.ROOT, "  %6.2f ns/number", cpu * 1e9 / numbers) : "",
                r);
    }

    /** What {@link #scanEveryField} read: the data lines, and a sum of their numbers (so no scan is optimised away). */
    record Scanned(long lines, double checksum) {
    }

    /**
     * Splits every line of {@code lines} and scans each of its {@code fields} numbers ({@link NumericRows},
     * every field selected): TUM's spaces, or a planar CSV with a header.
     */
    static Scanned scanEveryField(ByteLines lines, String name, boolean tum, int fields) {
        NumericRows r = new NumericRows(lines, name, tum ? NumericRows.WHITESPACE : (byte) ',', !tum);
        if (!tum) {
            r.nextContentLine();
        }
        int[] select = new int[fields];
        String[] names = new String[fields];
        String[] units = new String[fields];
        for (int k = 0; k < fields; k++) {
            select[k] = k;
            names[k] = "c" + k;
            units[k] = "";
        }
        r.select(select, names, units);
        r.requireFields(fields, "test");
        double[] row = new double[fields];
        long n = 0;
        double sum = 0;
        while (r.next(row)) {
            sum += row[1] + row[fields - 1];
            n++;
        }
        return new Scanned(n, sum);
    }
}
