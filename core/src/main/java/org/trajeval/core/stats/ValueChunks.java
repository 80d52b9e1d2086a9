package org.trajeval.core.stats;

/**
 * Values read in index order, chunk by chunk, as many times as asked: an array, or error values
 * computed afresh at each reading (so that a statistic of 10^7 errors needs no 80 MB array;
 * the values must come out bit for bit the same at every reading).
 */
public interface ValueChunks {
    /** @return the number of values */
    int size();

    /** Hands over consecutive chunks that cover all values in index order. */
    void forEach(Sink sink);

    /** Takes one chunk: {@code values[0..length)}, valid only during the call. */
    @FunctionalInterface
    interface Sink {
        void accept(double[] values, int length);
    }

    /** @return the first {@code n} values of {@code a}, as one chunk */
    static ValueChunks of(double[] a, int n) {
        return of(n, sink -> sink.accept(a, n));
    }

    /** @return {@code size} values that {@code producer} hands to a sink, in index order, at each reading */
    static ValueChunks of(int size, java.util.function.Consumer<Sink> producer) {
        return new ValueChunks() {
            @Override
            public int size() {
                return size;
            }

            @Override
            public void forEach(Sink sink) {
                producer.accept(sink);
            }
        };
    }
}
