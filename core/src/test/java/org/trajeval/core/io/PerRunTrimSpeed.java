package org.trajeval.core.io;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.nio.channels.FileChannel;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.report.ReportJson;

/**
 * Not a test: an A/B of two per-run trims inside one JVM, the variants alternated call by call
 * (which runs first alternates) so that the machine's load falls on both alike; prints the median thread CPU time per call
 * (us) of each variant per round.
 * {@code read PAIRS.csv PAIRS ROUNDS}: each file of the first PAIRS pairs read with a fresh 1 MiB
 * buffer (the spare one taken away first, as before {@link SpareBuffer}) and then with the spare.
 * {@code write DIR COUNT ROUNDS}: a 3 kB report written atomically into DIR by
 * {@link ReportJson#writeAtomically} and by the code it replaced ({@code createDirectories},
 * {@code Files.createTempFile}, a second open with truncate).
 * Usage: {@code java -cp core/build/classes/java/test:core/build/classes/java/main:cli/build/install/trajeval/lib/*
 * org.trajeval.core.io.PerRunTrimSpeed read|write ...}.
 */
public final class PerRunTrimSpeed {
    private PerRunTrimSpeed() {
    }

    public static void main(String[] args) throws Exception {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        int rounds = Integer.parseInt(args[3]);
        List<Runnable> before = new ArrayList<>();
        List<Runnable> after = new ArrayList<>();
        if (args[0].equals("read")) {
            List<String> lines = Files.readAllLines(Path.of(args[1]));
            for (String line : lines.subList(1, Math.min(lines.size(), Integer.parseInt(args[2]) + 1))) {
                for (String f : Arrays.asList(line.split(",")).subList(1, 3)) {
                    Path p = Path.of(f);
                    before.add(() -> {
                        SpareBuffer.take(); // dropped: the read allocates a fresh buffer
                        TrajectoryReader.read(p, ReadOptions.defaults());
                    });
                    after.add(() -> TrajectoryReader.read(p, ReadOptions.defaults()));
                }
            }
        } else {
            Path dir = Files.createDirectories(Path.of(args[1]));
            byte[] json = "{\"x\": 0.25}\n".repeat(256).getBytes(StandardCharsets.UTF_8);
            for (int k = 0; k < Integer.parseInt(args[2]); k++) {
                Path target = dir.resolve("r" + k + ".json");
                before.add(() -> writeAsBefore(target, json));
                after.add(() -> ReportJson.writeAtomically(target, json));
            }
        }
        for (int r = 0; r < rounds; r++) {
            long[] b = new long[before.size()];
            long[] a = new long[after.size()];
            for (int k = 0; k < b.length; k++) {
                boolean beforeFirst = (k + r) % 2 == 0; // neither variant always finds the file's bytes in the caches
                long c0 = mx.getCurrentThreadCpuTime();
                (beforeFirst ? before : after).get(k).run();
                long c1 = mx.getCurrentThreadCpuTime();
                (beforeFirst ? after : before).get(k).run();
                long c2 = mx.getCurrentThreadCpuTime();
                b[k] = beforeFirst ? c1 - c0 : c2 - c1;
                a[k] = beforeFirst ? c2 - c1 : c1 - c0;
            }
            Arrays.sort(b);
            Arrays.sort(a);
            System.out.printf(Locale.ROOT, "round %d: median us per call before %.1f after %.1f; mean %.1f / %.1f%n", r,
                    b[b.length / 2] / 1e3, a[a.length / 2] / 1e3, Arrays.stream(b).average().orElse(0) / 1e3,
                    Arrays.stream(a).average().orElse(0) / 1e3);
        }
    }

    /** The atomic write as it was at 6c2fbbb. */
    private static void writeAsBefore(Path target, byte[] bytes) {
        try {
            Path dir = target.toAbsolutePath().getParent();
            Files.createDirectories(dir);
            Path tmp = Files.createTempFile(dir, "." + target.getFileName() + ".", ".tmp");
            try (FileChannel ch = FileChannel.open(tmp, StandardOpenOption.WRITE, StandardOpenOption.TRUNCATE_EXISTING)) {
                java.io.OutputStream out = java.nio.channels.Channels.newOutputStream(ch);
                out.write(bytes);
                out.flush();
                ch.force(true);
            }
            Files.setPosixFilePermissions(tmp, PosixFilePermissions.fromString("rw-r--r--"));
            ReportJson.moveIntoPlace(tmp, target);
            ReportJson.fsyncDirectory(dir);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
