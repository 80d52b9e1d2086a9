package org.trajeval.cli;

import picocli.CommandLine.Option;

/** The options of the paired statistics shared by {@code suite} and {@code compare}. */
public final class StatisticsOptions {
    @Option(names = "--seed", paramLabel = "N", defaultValue = "1",
            description = "Seed of the bootstrap resampling (default: ${DEFAULT-VALUE}); same seed, same bytes.")
    long seed;

    @Option(names = "--confidence", paramLabel = "LEVEL", defaultValue = "0.95",
            converter = BoundedOptions.Confidence.class,
            description = "Confidence level of every interval (default: ${DEFAULT-VALUE}).")
    double confidence;

    @Option(names = "--resamples", paramLabel = "B", defaultValue = "4000",
            converter = BoundedOptions.Resamples.class,
            description = "Bootstrap resamples, 100 to 1000000 (default: ${DEFAULT-VALUE}).")
    int resamples;
}
