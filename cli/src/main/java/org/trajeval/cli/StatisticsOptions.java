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

    /** @throws org.trajeval.core.InputException on a level outside (0, 1) or fewer than 100 resamples */
    void check() {
        if (!(confidence > 0.0 && confidence < 1.0)) {
            throw UsageProblem.of("--confidence", "--confidence must be a level between 0 and 1 (exclusive)",
                    String.valueOf(confidence));
        }
        if (resamples < 100) {
            throw UsageProblem.of("--resamples", "--resamples must be at least 100", String.valueOf(resamples));
        }
        if (!(power > 0.5 && power < 1.0)) {
            throw UsageProblem.of("--power", "--power must be a probability between 0.5 and 1 (exclusive)",
                    String.valueOf(power));
        }
        for (Map.Entry<String, Double> e : detect.entrySet()) {
            if (e.getValue() == null || e.getValue() == 0.0 || !Double.isFinite(e.getValue())) {
                throw UsageProblem.of("--detect", "--detect " + e.getKey() + " must be a finite non-zero difference",
                        String.valueOf(e.getValue()));
            }
        }
    }

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
        check();
        return new org.trajeval.core.protocol.SuiteAnalysis.Settings(seed, confidence, resamples, power, detect);
    }
}
