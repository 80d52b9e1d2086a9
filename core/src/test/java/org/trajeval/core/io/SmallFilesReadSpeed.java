package org.trajeval.core.io;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Not a test: reads many small files one after the other on one thread, as {@code eval --batch}
 * and the pipeline read each pair's files ({@link TrajectoryReader#read(Path, ReadOptions)}, from
 * disk, format detected), {@code rounds} times over the same files in one JVM, and prints each
 * round's thread CPU time per file (the first round includes the JIT's warm-up on this thread).
 * Usage: {@code java -cp ... org.trajeval.core.io.SmallFilesReadSpeed PAIRS.csv PAIRS ROUNDS}: the
 * reference and estimate of the first {@code PAIRS} lines of an {@code eval --batch} pairs file
 * ({@code name,ref,est}).
 */
public final class SmallFilesReadSpeed {
    private SmallFilesReadSpeed() {
    }

    public static void main(String[] args) throws Exception {
        List<String> lines = Files.readAllLines(Path.of(args[0]));
        int pairs = Integer.parseInt(args[1]);
        int rounds = Integer.parseInt(args[2]);
        List<Path> files = new ArrayList<>();
        for (String line : lines.subList(1, Math.min(lines.size(), pairs + 1))) {
            String[] f = line.split(",");
            files.add(Path.of(f[1]));
            files.add(Path.of(f[2]));
        }
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        ReadOptions options = ReadOptions.defaults();
        long poses = 0;
        StringBuilder out = new StringBuilder();
        double best = Double.MAX_VALUE;
        for (int r = 0; r < rounds; r++) {
            long c0 = mx.getCurrentThreadCpuTime();
            for (Path p : files) {
                poses += TrajectoryReader.read(p, options).trajectory().size();
            }
            double perFile = (mx.getCurrentThreadCpuTime() - c0) * 1e-3 / files.size();
            best = Math.min(best, perFile);
            out.append(String.format(Locale.ROOT, " %.0f", perFile));
        }
        System.out.printf(Locale.ROOT, "%d files, us CPU per file by round:%s | best %.0f us (%d poses)%n",
                files.size(), out, best, poses);
    }
}
