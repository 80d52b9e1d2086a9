package org.trajeval.cli;

import picocli.CommandLine.Option;

/** The options of the paired statistics shared by {@code suite} and {@code compare}. */
public final class StatisticsOptions {
    @Option(names = "--seed", paramLabel = "N", defaultValue = "1",
            description = "Seed of the bootstrap resampling (default: ${DEFAULT-VALUE}); same seed, same bytes.")
    long seed;

    @Option(names = "--confidence", paramLabel = "LEVEL", defaultValue = "0.95",
            description = "Confidence level of every interval (default: ${DEFAULT-VALUE}).")
    double confidence;

    @Option(names = "--resamples", paramLabel = "B", defaultValue = "4000",
            description = "Bootstrap resamples (default: ${DEFAULT-VALUE}).")
    int resamples;

    /** @throws org.trajeval.core.InputException on a level outside (0, 1) or fewer than 100 resamples */
    void check() {
        if (!(confidence > 0.0 && confidence < 1.0)) {
            throw UsageProblem.of("--confidence", "--confidence must be a level between 0 and 1 (exclusive)",
                    String.valueOf(confidence));
        }
        if (resamples < 100) {
            throw UsageProblem.of("--resamples", "--resamples must be at least 100", String.valueOf(resamples));
        }
    }
}
