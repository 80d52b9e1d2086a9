package org.trajeval.cli;

import java.util.LinkedHashMap;
import java.util.Map;
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

    @Option(names = "--power", paramLabel = "P", defaultValue = "0.8",
            description = "Power of the planning figures: the smallest mean difference each comparison detects "
                + "with this probability (default: ${DEFAULT-VALUE}).")
    double power;

    @Option(names = "--detect", paramLabel = "METRIC=DIFF",
            description = "Report how many sequences a mean difference DIFF on METRIC (its unit, e.g. "
                + "ate_trans_rmse_m=0.01, or score=2) needs at --confidence and --power; repeatable.")
    Map<String, Double> detect = new LinkedHashMap<>();

    /** @return the core's statistics settings */
    org.trajeval.core.protocol.SuiteAnalysis.Settings analysis() {
        return new org.trajeval.core.protocol.SuiteAnalysis.Settings(seed, confidence, resamples, power, detect);
    }
}
