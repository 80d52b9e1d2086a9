package org.trajeval.cli;

import java.nio.file.Path;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.ReadThreads;
import org.trajeval.core.io.TrajectoryReader;

/**
 * The threads of one {@code trajeval eval}: the two files are read at once when a second thread is
 * allowed (parsing is the floor of eval's time), and the evaluation spreads its element-wise passes
 * over all of them.
 */
final class EvalThreads implements AutoCloseable {
    private final int threads;
    private final ExecutorService pool;

    /** @param threads threads in all, the caller's included */
    EvalThreads(int threads) {
        if (threads < 1) {
            throw UsageProblem.of("--threads", "--threads must be at least 1", String.valueOf(threads));
        }
        this.threads = threads;
        this.pool = threads == 1 ? null : Executors.newFixedThreadPool(threads - 1, r -> {
            Thread t = new Thread(r, "trajeval-worker");
            t.setDaemon(true);
            return t;
        });
    }

    /** @return how the evaluation may spread its work */
    org.trajeval.core.eval.Parallelism parallelism() {
        return pool == null ? org.trajeval.core.eval.Parallelism.SEQUENTIAL
                : new org.trajeval.core.eval.Parallelism(pool, threads);
    }

    /**
     * Reads the reference and the estimate, the estimate on a second thread when there is one; a
     * thread whose file is done (or an idle one) helps parse the blocks of a big file still being read
     * ({@link ReadThreads#forPair}: where one file is at least twice the other's size, or with more
     * threads than files).
     */
    LoadedTrajectory[] both(ReadOptions refOptions, Path reference, ReadOptions estOptions, Path estimate) {
        if (pool == null) {
            return new LoadedTrajectory[] {TrajectoryReader.read(reference, refOptions),
                TrajectoryReader.read(estimate, estOptions)};
        }
        ReadThreads readers = ReadThreads.forPair(pool, threads, reference, estimate);
        if (readers.readSecondHere()) {
            return biggerEstimateHere(readers, refOptions, reference, estOptions, estimate);
        }
        Future<LoadedTrajectory> est = pool.submit(() -> TrajectoryReader.read(estimate, estOptions, readers));
        LoadedTrajectory ref;
        try {
            ref = TrajectoryReader.read(reference, refOptions, readers);
        } catch (RuntimeException e) {
            est.cancel(true);
            throw e;
        }
        return new LoadedTrajectory[] {ref, join(est)};
    }

    /**
     * The bigger estimate on this thread and the reference on the pool's ({@link ReadThreads#readSecondHere});
     * a refusal of the reference still comes first, as when the reference is read here.
     */
    private LoadedTrajectory[] biggerEstimateHere(ReadThreads readers, ReadOptions refOptions, Path reference,
            ReadOptions estOptions, Path estimate) {
        Future<LoadedTrajectory> ref = pool.submit(() -> TrajectoryReader.read(reference, refOptions, readers));
        LoadedTrajectory est;
        try {
            est = TrajectoryReader.read(estimate, estOptions, readers);
        } catch (RuntimeException e) {
            join(ref);
            throw e;
        }
        return new LoadedTrajectory[] {join(ref), est};
    }

    @Override
    public void close() {
        if (pool != null) {
            pool.shutdownNow();
        }
    }

    private static LoadedTrajectory join(Future<LoadedTrajectory> f) {
        try {
            return f.get();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while reading", e);
        } catch (ExecutionException e) {
            Throwable c = e.getCause();
            if (c instanceof RuntimeException re) {
                throw re;
            }
            if (c instanceof Error err) {
                throw err;
            }
            throw new IllegalStateException(c);
        }
    }
}
