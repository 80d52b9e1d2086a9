package org.trajeval.core.io;

import java.lang.management.ManagementFactory;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;

/**
 * Not a test: reads two files on two threads as {@code eval --threads 2} does (the estimate on a
 * pool thread, the reference on the calling one) in a fresh JVM, and prints the wall time, the
 * process CPU time and each thread's CPU time and finishing time (s from the start of the reads).
 * Usage: {@code java -cp ... org.trajeval.core.io.ReadPairSpeed REF EST [WARM_REF WARM_EST]...}:
 * each warm-up pair is read the same way first (so that a cold and a warm read can be told apart).
 */
public final class ReadPairSpeed {
    private ReadPairSpeed() {
    }

    public static void main(String[] args) throws Exception {
        Path ref = Path.of(args[0]);
        Path est = Path.of(args[1]);
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        com.sun.management.OperatingSystemMXBean os =
                (com.sun.management.OperatingSystemMXBean) ManagementFactory.getOperatingSystemMXBean();
        ExecutorService pool = Executors.newSingleThreadExecutor();
        try {
            for (int w = 2; w + 1 < args.length; w += 2) {
                Path warmEst = Path.of(args[w + 1]);
                Future<?> f = pool.submit(() -> TrajectoryReader.read(warmEst, ReadOptions.defaults()));
                TrajectoryReader.read(Path.of(args[w]), ReadOptions.defaults());
                f.get();
            }
            long p0 = os.getProcessCpuTime();
            long t0 = System.nanoTime();
            Future<double[]> worker = pool.submit(() -> {
                long c = mx.getCurrentThreadCpuTime();
                TrajectoryReader.read(est, ReadOptions.defaults());
                return new double[] {(mx.getCurrentThreadCpuTime() - c) * 1e-9, (System.nanoTime() - t0) * 1e-9};
            });
            long c = mx.getCurrentThreadCpuTime();
            TrajectoryReader.read(ref, ReadOptions.defaults());
            double mainCpu = (mx.getCurrentThreadCpuTime() - c) * 1e-9;
            double mainDone = (System.nanoTime() - t0) * 1e-9;
            double[] w = worker.get();
            System.out.printf(Locale.ROOT,
                    "wall %.3f s, process CPU %.3f s | reference (calling thread): CPU %.3f s, done at %.3f s"
                            + " | estimate (pool thread): CPU %.3f s, done at %.3f s%n",
                    (System.nanoTime() - t0) * 1e-9, (os.getProcessCpuTime() - p0) * 1e-9, mainCpu, mainDone, w[0],
                    w[1]);
        } finally {
            pool.shutdown();
        }
    }
}
