package org.trajeval.cli;

import java.nio.file.Path;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.trajeval.core.io.LoadedTrajectory;

/** Reads the reference and the estimate, on two threads when allowed (parsing is the floor of eval's time). */
final class ParallelRead {
    private ParallelRead() {
    }

    static LoadedTrajectory[] both(InputOptions input, Path reference, Path estimate, int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("--threads must be at least 1, found " + threads);
        }
        if (threads == 1) {
            return new LoadedTrajectory[] {input.read(reference, true), input.read(estimate, false)};
        }
        ExecutorService pool = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "trajeval-read");
            t.setDaemon(true);
            return t;
        });
        try {
            Future<LoadedTrajectory> est = pool.submit(() -> input.read(estimate, false));
            LoadedTrajectory ref = input.read(reference, true);
            return new LoadedTrajectory[] {ref, join(est)};
        } finally {
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
