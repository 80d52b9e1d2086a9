package org.trajeval.pipeline;

/** The scorer of the pipeline's end-to-end tests: always the real core engine. */
public final class TestScorers {
    private TestScorers() {
    }

    /** @return the real scorer (256 MiB input budget per run), the one the service runs */
    public static RunScorer real() {
        return new CoreRunScorer(256L << 20);
    }
}
