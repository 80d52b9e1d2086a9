package org.trajeval.core.io;

import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;

/**
 * The helper threads the block-read tests share: a pool of 2 started before a test class and stopped
 * after it, and {@link ReadThreads} of 3 units over it (the calling thread and the pool's two).
 */
abstract class ReadPoolFixture {
    static ExecutorService pool;

    @BeforeAll
    static void startPool() {
        pool = Executors.newFixedThreadPool(2);
    }

    @AfterAll
    static void stopPool() {
        pool.shutdownNow();
    }

    /** @return three threads reading blocks of {@code block} bytes over the shared pool */
    static ReadThreads threads(int block) {
        return new ReadThreads(pool, 3, block);
    }
}
