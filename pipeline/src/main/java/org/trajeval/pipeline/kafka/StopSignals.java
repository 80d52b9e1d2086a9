package org.trajeval.pipeline.kafka;

import java.util.ArrayList;
import java.util.List;
import sun.misc.Signal;
import sun.misc.SignalHandler;

/**
 * SIGTERM and SIGINT end the Kafka mode cleanly: they ask the service to stop after its current
 * transaction, and the launcher then exits with 0 (without this, the JVM would exit with 143 or
 * 130 while the service is still committing). The previous handlers come back on {@link #close()}.
 */
final class StopSignals implements AutoCloseable {
    private final List<Signal> signals = new ArrayList<>();
    private final List<SignalHandler> previous = new ArrayList<>();

    private StopSignals() {
    }

    /** Installs {@code onStop} for SIGTERM and SIGINT (where the JVM lets us). */
    static StopSignals install(Runnable onStop) {
        StopSignals s = new StopSignals();
        for (String name : List.of("TERM", "INT")) {
            try {
                Signal sig = new Signal(name);
                s.previous.add(Signal.handle(sig, x -> onStop.run()));
                s.signals.add(sig);
            } catch (IllegalArgumentException e) {
                // -Xrs or a signal the JVM keeps for itself: the default handling stays
            }
        }
        return s;
    }

    @Override
    public void close() {
        for (int i = 0; i < signals.size(); i++) {
            Signal.handle(signals.get(i), previous.get(i));
        }
    }
}
