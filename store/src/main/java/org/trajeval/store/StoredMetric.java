package org.trajeval.store;

import java.util.ArrayList;
import java.util.List;
import org.trajeval.core.protocol.RunMetric;

/**
 * The metric columns of the {@code runs} table: the run metrics of core (named with their unit),
 * the suite's normalised score and the coverage fraction. The column name is the key.
 */
public final class StoredMetric {
    /** Normalised score S in [0, 100] (higher is better); suites only. */
    public static final String SCORE = "score";
    /** Fraction of the reference's time span covered by the estimate, in [0, 1]. */
    public static final String COVERAGE = "coverage";

    private static final List<String> KEYS;

    static {
        List<String> k = new ArrayList<>();
        k.add(COVERAGE);
        for (RunMetric m : RunMetric.values()) {
            k.add(m.key());
        }
        k.add(SCORE);
        KEYS = List.copyOf(k);
    }

    private StoredMetric() {
    }

    /** @return every metric column, in table order */
    public static List<String> keys() {
        return KEYS;
    }

    /** @return whether higher values are better (the score, the coverage) */
    public static boolean higherIsBetter(String key) {
        return SCORE.equals(key) || COVERAGE.equals(key);
    }

    /** @throws StoreException BAD_QUERY when {@code key} is no metric column */
    public static String require(String key) {
        if (!KEYS.contains(key)) {
            throw new StoreException(StoreException.Problem.BAD_QUERY,
                    "--metric: expected one of " + String.join(", ", KEYS) + ", found \"" + key + "\"", null);
        }
        return key;
    }
}
