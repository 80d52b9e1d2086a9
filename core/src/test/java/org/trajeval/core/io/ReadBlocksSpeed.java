package org.trajeval.core.io;

import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

/**
 * Not a test: reads one file, or a pair as {@code eval --threads 2} does (the estimate on the pool
 * thread), RUNS times in one JVM, each file either as a whole ({@code whole}: {@link ReadThreads#ONE},
 * a pair on two threads as before) or in blocks ({@code blocks}: {@link ReadThreads} over the pool),
 * and prints each run's wall time and process CPU time (the first run is the cold one).
 * Usage: {@code java -cp ... org.trajeval.core.io.ReadBlocksSpeed whole|blocks[:MIB] RUNS FILE [FILE2]}
 * (MIB: the block size in MiB).
 */
public final class ReadBlocksSpeed {
    private ReadBlocksSpeed() {
    }

    public static void main(String[] args) throws Exception {
        boolean blocks = args[0].startsWith("blocks");
        long blockBytes = args[0].startsWith("blocks:") ? Long.parseLong(args[0].substring(7)) << 20
                : ReadThreads.BLOCK_BYTES;
        int runs = Integer.parseInt(args[1]);
        Path ref = Path.of(args[2]);
        Path est = args.length > 3 ? Path.of(args[3]) : null;
        com.sun.management.OperatingSystemMXBean os =
                (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        ExecutorService pool = Executors.newSingleThreadExecutor();
        ReadThreads threads = blocks ? new ReadThreads(pool, 2, blockBytes) : ReadThreads.ONE;
        try {
            for (int r = 0; r < runs; r++) {
                long p0 = os.getProcessCpuTime();
                long t0 = System.nanoTime();
                Future<LoadedTrajectory> other = est == null ? null
                        : pool.submit(() -> TrajectoryReader.read(est, ReadOptions.defaults(), threads));
                int n = TrajectoryReader.read(ref, ReadOptions.defaults(), threads).trajectory().size();
                if (other != null) {
                    n += other.get().trajectory().size();
                }
                System.out.printf(Locale.ROOT, "%s run %d: %d poses, wall %.3f s, process CPU %.3f s%n", args[0], r, n,
                        (System.nanoTime() - t0) * 1e-9, (os.getProcessCpuTime() - p0) * 1e-9);
            }
        } finally {
            pool.shutdown();
        }
    }
}
