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
            converter = BoundedOptions.Confidence.class,
            description = "Confidence level of every interval (default: ${DEFAULT-VALUE}).")
    double confidence;

    @Option(names = "--resamples", paramLabel = "B", defaultValue = "4000",
            converter = BoundedOptions.Resamples.class,
            description = "Bootstrap resamples, 100 to 1000000 (default: ${DEFAULT-VALUE}).")
    int resamples;

    @Option(names = "--power", paramLabel = "P", defaultValue = "0.8",
            description = "Power of the planning figures: the smallest mean difference each comparison detects "
                + "with this probability (default: ${DEFAULT-VALUE}).")
    double power;

    @Option(names = "--detect", paramLabel = "METRIC=DIFF",
            description = "Report how many sequences a mean difference DIFF on METRIC (its unit, e.g. "
                + "ate_trans_rmse_m=0.01, or score=2) needs at --confidence and --power; repeatable.")
    Map<String, Double> detect = new LinkedHashMap<>();

    /**
     * @param allowLeakage run despite split leakage
     * @return the suite's settings, checked by the core's one check of these options
     * @throws org.trajeval.core.InputException (exit 2) on a level outside (0, 1), resamples outside 100 to
     *     10^6, a power outside (0.5, 1) or a zero or non-finite {@code --detect} difference
     */
    org.trajeval.core.protocol.SuiteRunner.Settings suite(boolean allowLeakage) {
        return new org.trajeval.core.protocol.SuiteRunner.Settings(seed, allowLeakage, confidence, resamples, power,
                detect).checked();
    }

    /** @return the core's statistics settings, checked as {@link #suite} checks them */
    org.trajeval.core.protocol.SuiteAnalysis.Settings analysis() {
        suite(false);
        return new org.trajeval.core.protocol.SuiteAnalysis.Settings(seed, confidence, resamples, power, detect);
    }
}
