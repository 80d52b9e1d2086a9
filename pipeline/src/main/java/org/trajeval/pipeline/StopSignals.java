package org.trajeval.pipeline;

import java.util.ArrayList;
import java.util.List;
import sun.misc.Signal;
import sun.misc.SignalHandler;

/**
 * SIGTERM and SIGINT end either mode cleanly: they ask the service to stop (the directory mode
 * after its runs in hand, the Kafka mode after its current transaction), and the launcher then
 * exits with its normal code, 0 (without this, the JVM would run its shutdown hooks and exit with
 * 143 or 130). The previous handlers come back on {@link #close()}.
 */
public final class StopSignals implements AutoCloseable {
    private final List<Signal> signals = new ArrayList<>();
    private final List<SignalHandler> previous = new ArrayList<>();

    private StopSignals() {
    }

    /** Installs {@code onStop} for SIGTERM and SIGINT (where the JVM lets us). */
    public static StopSignals install(Runnable onStop) {
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
