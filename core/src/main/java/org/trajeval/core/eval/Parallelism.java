package org.trajeval.core.eval;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import org.trajeval.core.assoc.IndexTasks;

/**
 * How many threads an evaluation may use, and the executor that lends the extra ones (the
 * caller's thread always works too). Work is cut into fixed chunks of {@link #CHUNK} indices
 * whatever the thread count, and per-chunk partial results are combined in chunk order, so a
 * result does not depend on the number of threads.
 *
 * @param executor runs the {@code threads - 1} helper tasks; unused (may be null) when threads is 1
 * @param threads threads working at once, the caller's included (at least 1)
 */
public record Parallelism(ExecutorService executor, int threads) implements IndexTasks {
    /** Indices per chunk. */
    static final int CHUNK = 1 << 16;

    /** One thread: everything on the caller's thread. */
    public static final Parallelism SEQUENTIAL = new Parallelism(null, 1);

    /** @throws IllegalArgumentException when threads &lt; 1, or &gt; 1 without an executor */
    public Parallelism {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be at least 1, got " + threads);
        }
        if (threads > 1 && executor == null) {
            throw new IllegalArgumentException("more than one thread needs an executor");
        }
    }

    /** Work on the index range [from, to) of one chunk. */
    @FunctionalInterface
    interface ChunkWork {
        void run(int chunk, int from, int to);
    }

    /** @return the number of chunks that cover [0, n) */
    static int chunks(int n) {
        return (int) (((long) n + CHUNK - 1) / CHUNK);
    }

    /** Runs {@code work} on every chunk of [0, n), on up to {@link #threads()} threads; returns when all are done. */
    void forEachChunk(int n, ChunkWork work) {
        forEach(chunks(n), c -> work.run(c, c * CHUNK, (int) Math.min((long) (c + 1) * CHUNK, n)));
    }

    /**
     * Runs every task once, on up to {@link #threads()} threads; returns when all are done (one
     * thread: in the order given). For independent passes that each keep their own order of
     * operations, e.g. two sums over different arrays: each gives the same bits wherever it runs.
     */
    void all(Runnable... tasks) {
        forEach(tasks.length, c -> tasks[c].run());
    }

    /**
     * Runs {@code task} for every index in [0, tasks), on up to {@link #threads()} threads (the
     * caller's included), each index once, in no fixed order; returns when all are done. The first
     * exception of a task is rethrown after every thread has stopped.
     */
    @Override
    public void forEach(int tasks, java.util.function.IntConsumer task) {
        if (threads == 1 || tasks < 2) {
            for (int c = 0; c < tasks; c++) {
                task.accept(c);
            }
            return;
        }
        AtomicInteger next = new AtomicInteger();
        Runnable worker = () -> {
            for (int c = next.getAndIncrement(); c < tasks; c = next.getAndIncrement()) {
                task.accept(c);
            }
        };
        int helpers = Math.min(threads, tasks) - 1;
        List<Future<?>> futures = new ArrayList<>(helpers);
        for (int h = 0; h < helpers; h++) {
            futures.add(executor.submit(worker));
        }
        RuntimeException failure = null;
        try {
            worker.run();
        } catch (RuntimeException e) {
            failure = e;
            next.set(tasks);
        }
        for (Future<?> f : futures) {
            try {
                f.get();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("interrupted while evaluating", e);
            } catch (ExecutionException e) {
                if (failure == null) {
                    Throwable cause = e.getCause();
                    if (cause instanceof Error err) {
                        throw err;
                    }
                    failure = cause instanceof RuntimeException re ? re : new IllegalStateException(cause);
                }
            }
        }
        if (failure != null) {
            throw failure;
        }
    }
}
