package org.trajeval.core.io;

import java.util.function.BooleanSupplier;

/**
 * Waiting on a monitor where an interrupt must not abandon the wait (a read in blocks finishes or
 * falls back as a whole; it never leaves other threads' blocks half-read): the interrupt is noted and
 * set again on the thread once the wait is over.
 */
final class KeptInterrupt {
    private KeptInterrupt() {
    }

    /**
     * Waits on {@code monitor}, whose lock the calling thread holds, until {@code done} is true
     * (checked under that lock, before each wait); an interrupt meanwhile is kept, not thrown.
     */
    static void await(Object monitor, BooleanSupplier done) {
        boolean interrupted = false;
        while (!done.getAsBoolean()) {
            try {
                monitor.wait();
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }
}
