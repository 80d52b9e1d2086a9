package org.trajeval.core.assoc;

import java.util.function.IntConsumer;

/**
 * Runs independent tasks 0, 1, ..., n - 1: on the caller's thread in order ({@link #SERIAL}), or
 * spread over several threads (the evaluator's {@code Parallelism}). A computation cut into such
 * tasks gives the same result however they are run.
 */
@FunctionalInterface
public interface IndexTasks {
    /** Runs {@code task} for every index in [0, tasks), each once, in any order; returns when all are done. */
    void forEach(int tasks, IntConsumer task);

    /** Every task on the caller's thread, in index order. */
    IndexTasks SERIAL = (tasks, task) -> {
        for (int c = 0; c < tasks; c++) {
            task.accept(c);
        }
    };
}
