package org.trajeval.core.report;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;
import org.trajeval.core.report.SuiteReport.Bounds;

/**
 * The simulation-to-reality section of a suite report ({@code domain_gap}, lesson section 8): per
 * score metric and method the losses in each domain, the transfer gap Delta_gap = L_real - L_sim
 * with a bootstrap interval, the rankings in each domain, Kendall's tau between them and every pair
 * of methods whose order flips.
 *
 * @param simSequences evaluated sequences of domain sim
 * @param realSequences evaluated sequences of domain real
 * @param pairedScenarios scenarios with both a sim and a real sequence
 * @param intervalMethod {@code paired_over_scenarios} (scenarios resampled whole) or
 *     {@code independent_domains} (each domain's sequences resampled on their own)
 * @param intervalReason why that method applies, one sentence
 * @param level confidence level of the intervals
 * @param resamples bootstrap resamples
 * @param metrics one entry per score metric and the score
 */
@JsonPropertyOrder({"sim_sequences", "real_sequences", "paired_scenarios", "interval_method", "interval_reason",
    "level", "resamples", "metrics"})
@JsonInclude(JsonInclude.Include.ALWAYS)
public record DomainGapReport(@JsonProperty("sim_sequences") List<String> simSequences,
        @JsonProperty("real_sequences") List<String> realSequences,
        @JsonProperty("paired_scenarios") List<String> pairedScenarios,
        @JsonProperty("interval_method") String intervalMethod,
        @JsonProperty("interval_reason") String intervalReason, @JsonProperty("level") double level,
        @JsonProperty("resamples") int resamples, @JsonProperty("metrics") List<MetricGap> metrics) {

    /**
     * @param metric metric key, or {@code score}
     * @param better lower or higher
     * @param methods one entry per method, in manifest order
     * @param kendallTau tau_b between the sim and the real ranking (null when undefined)
     * @param flips pairs of methods ordered one way in sim and the other way in real
     */
    @JsonPropertyOrder({"metric", "better", "methods", "kendall_tau", "flips"})
    public record MetricGap(@JsonProperty("metric") String metric, @JsonProperty("better") String better,
            @JsonProperty("methods") List<MethodGap> methods, @JsonProperty("kendall_tau") Double kendallTau,
            @JsonProperty("flips") List<Flip> flips) {
    }

    /**
     * @param method method name
     * @param nSim sim sequences with a value
     * @param nReal real sequences with a value
     * @param lSim L_sim: mean over the sim sequences of the per-sequence means over seeds
     * @param lReal L_real, likewise over the real sequences
     * @param gap Delta_gap = L_real - L_sim (unit of the metric)
     * @param gapInterval bootstrap percentile interval of the gap
     * @param rankSim rank among the methods in sim (1 = best, ties mid-ranked), null without L_sim
     * @param rankReal rank in real
     */
    @JsonPropertyOrder({"method", "n_sim", "n_real", "l_sim", "l_real", "gap", "gap_interval", "rank_sim",
        "rank_real"})
    public record MethodGap(@JsonProperty("method") String method, @JsonProperty("n_sim") int nSim,
            @JsonProperty("n_real") int nReal, @JsonProperty("l_sim") Double lSim,
            @JsonProperty("l_real") Double lReal, @JsonProperty("gap") Double gap,
            @JsonProperty("gap_interval") Bounds gapInterval, @JsonProperty("rank_sim") Double rankSim,
            @JsonProperty("rank_real") Double rankReal) {
    }

    /**
     * @param methodA first method (manifest order)
     * @param methodB second method
     * @param betterInSim the method better in simulation
     * @param betterInReal the method better in reality
     * @param gapDifference Delta_gap(A) - Delta_gap(B)
     * @param gapDifferenceInterval its bootstrap interval (same resamples as the gaps)
     * @param sim the paired comparison A - B over the sim sequences
     * @param real the paired comparison A - B over the real sequences
     * @param supported true when both sides' paired comparisons support their order
     */
    @JsonPropertyOrder({"method_a", "method_b", "better_in_sim", "better_in_real", "gap_difference",
        "gap_difference_interval", "sim", "real", "supported"})
    public record Flip(@JsonProperty("method_a") String methodA, @JsonProperty("method_b") String methodB,
            @JsonProperty("better_in_sim") String betterInSim, @JsonProperty("better_in_real") String betterInReal,
            @JsonProperty("gap_difference") Double gapDifference,
            @JsonProperty("gap_difference_interval") Bounds gapDifferenceInterval,
            @JsonProperty("sim") Side sim, @JsonProperty("real") Side real,
            @JsonProperty("supported") boolean supported) {
    }

    /**
     * One domain's paired comparison of the two methods of a flip (the suite's comparison rules).
     *
     * @param n paired sequences
     * @param meanDifference mean of A - B
     * @param bootstrap bootstrap interval of the mean difference
     * @param wilcoxonP two-sided Wilcoxon signed-rank p
     * @param test the test the conclusion rests on (as in comparisons)
     * @param supports true when that test finds the difference at the level, in this domain's order
     */
    @JsonPropertyOrder({"n", "mean_difference", "bootstrap", "wilcoxon_p", "test", "supports"})
    public record Side(@JsonProperty("n") int n, @JsonProperty("mean_difference") Double meanDifference,
            @JsonProperty("bootstrap") Bounds bootstrap, @JsonProperty("wilcoxon_p") Double wilcoxonP,
            @JsonProperty("test") String test, @JsonProperty("supports") boolean supports) {
    }
}
