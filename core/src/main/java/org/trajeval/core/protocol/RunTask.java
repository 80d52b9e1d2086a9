package org.trajeval.core.protocol;

import java.io.Serializable;
import java.util.Objects;

/**
 * One run of a suite to score: a method's estimate of one sequence with one seed. The settings of
 * the run are the manifest's (suite, then sequence, then method), resolved by the {@link RunScorer}
 * of that manifest; a task is small and serialisable, so a cluster can ship it to a worker.
 *
 * @param index position in the plan (the order of the report's runs)
 * @param method method name
 * @param sequence sequence id
 * @param seed the seed of the run
 * @param estimate the estimate's path relative to the manifest's folder, as the method's pattern gives it
 */
public record RunTask(int index, String method, String sequence, long seed, String estimate) implements Serializable {
    private static final long serialVersionUID = 1L;

    /** @throws NullPointerException on a missing component */
    public RunTask {
        Objects.requireNonNull(method, "method");
        Objects.requireNonNull(sequence, "sequence");
        Objects.requireNonNull(estimate, "estimate");
    }
}
