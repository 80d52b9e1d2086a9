package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;
import java.util.SplittableRandom;
import java.util.function.DoubleSupplier;
import org.junit.jupiter.api.Test;

/**
 * Statistics of values handed over chunk by chunk (errors computed afresh at each reading) must
 * be those of the same values in one array, bit for bit.
 */
class ChunkedStatisticsTest {
    /** The values of {@code a} in chunks of {@code chunk} values, copied out afresh at each reading. */
    private static ValueChunks inChunks(double[] a, int chunk) {
        return new ValueChunks() {
            @Override
            public int size() {
                return a.length;
            }

            @Override
            public void forEach(Sink sink) {
                double[] scratch = new double[chunk];
                for (int from = 0; from < a.length; from += chunk) {
                    int len = Math.min(chunk, a.length - from);
                    System.arraycopy(a, from, scratch, 0, len);
                    Arrays.fill(scratch, len, chunk, Double.NaN); // a sink must not read past len
                    sink.accept(scratch, len);
                }
            }
        };
    }

    private static double[] values(int n, DoubleSupplier next) {
        double[] a = new double[n];
        for (int i = 0; i < n; i++) {
            a[i] = next.getAsDouble();
        }
        return a;
    }

    @Test
    void chunkedValuesGiveTheStatisticsOfTheArrayBitForBit() {
        SplittableRandom rnd = new SplittableRandom(31);
        double[][] cases = {
            values(100_001, () -> Math.abs(0.05 * gaussian(rnd))), // errors, odd count
            values(100_000, () -> Math.abs(0.01 * gaussian(rnd))), // errors, even count
            values(70_000, () -> 1.0 + 1e-12 * rnd.nextDouble()), // clustered: refining passes
            values(50_000, () -> rnd.nextInt(3)), // many exact duplicates
            values(60_000, () -> rnd.nextDouble() - 0.5), // negative values: the copying path
            values(1_000, rnd::nextDouble), // small: the copying path
            new double[0]};
        for (double[] a : cases) {
            ErrorStatistics expected = ErrorStatistics.of(a, a.length);
            for (int chunk : new int[] {1 << 16, 4096, 777}) {
                assertEquals(expected, ErrorStatistics.of(inChunks(a, chunk)), a.length + " values in chunks of " + chunk);
            }
        }
    }

    private static double gaussian(SplittableRandom rnd) {
        // Box-Muller, enough for test data
        return Math.sqrt(-2 * Math.log(1 - rnd.nextDouble())) * Math.cos(2 * Math.PI * rnd.nextDouble());
    }
}
