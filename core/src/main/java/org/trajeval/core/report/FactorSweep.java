package org.trajeval.core.report;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;

/**
 * One stress sweep of a suite report ({@code factor_sweeps}): how each method fares as one
 * controlled factor (lesson section 8: "controlled variation of one factor at a time") grows.
 *
 * @param factor the factor's name
 * @param sequences evaluated sequences that declare the factor
 * @param levels the factor's levels, ascending
 * @param breakdownRate failure rate at which a method counts as broken down
 * @param methods one entry per method, in manifest order
 */
@JsonPropertyOrder({"factor", "sequences", "levels", "breakdown_rate", "methods"})
@JsonInclude(JsonInclude.Include.ALWAYS)
public record FactorSweep(@JsonProperty("factor") String factor, @JsonProperty("sequences") List<String> sequences,
        @JsonProperty("levels") List<Double> levels, @JsonProperty("breakdown_rate") double breakdownRate,
        @JsonProperty("methods") List<MethodSweep> methods) {

    /**
     * @param method method name
     * @param levels one entry per level, ascending
     * @param breakdownLevel lowest level whose failure rate reaches the breakdown rate, or null
     * @param sensitivity per metric, Kendall's tau_b between the level and the runs' values
     */
    @JsonPropertyOrder({"method", "levels", "breakdown_level", "sensitivity"})
    public record MethodSweep(@JsonProperty("method") String method, @JsonProperty("levels") List<Level> levels,
            @JsonProperty("breakdown_level") Double breakdownLevel,
            @JsonProperty("sensitivity") List<Sensitivity> sensitivity) {
    }

    /**
     * @param level the factor's level
     * @param sequences sequences at this level
     * @param runs runs at this level
     * @param failures failed runs
     * @param failureRate failure rate with its intervals (as per method)
     * @param metrics per score metric and the score: median and interval over the runs
     */
    @JsonPropertyOrder({"level", "sequences", "runs", "failures", "failure_rate", "metrics"})
    public record Level(@JsonProperty("level") double level, @JsonProperty("sequences") int sequences,
            @JsonProperty("runs") int runs, @JsonProperty("failures") int failures,
            @JsonProperty("failure_rate") SuiteReport.Proportion failureRate,
            @JsonProperty("metrics") List<LevelMetric> metrics) {
    }

    /**
     * @param metric metric key or {@code score}
     * @param n values (successful runs; every run for the score)
     * @param median their median
     * @param lower lower bound of the order-statistic interval of the median
     * @param upper upper bound
     * @param achievedLevel the interval's achieved level (below the level asked for n &lt; 6)
     */
    @JsonPropertyOrder({"metric", "n", "median", "lower", "upper", "achieved_level"})
    public record LevelMetric(@JsonProperty("metric") String metric, @JsonProperty("n") int n,
            @JsonProperty("median") Double median, @JsonProperty("lower") Double lower,
            @JsonProperty("upper") Double upper, @JsonProperty("achieved_level") Double achievedLevel) {
    }

    /**
     * @param metric metric key or {@code score}
     * @param n runs with a value
     * @param kendallTau tau_b between level and value (positive: the value grows with the level), or null
     */
    @JsonPropertyOrder({"metric", "n", "kendall_tau"})
    public record Sensitivity(@JsonProperty("metric") String metric, @JsonProperty("n") int n,
            @JsonProperty("kendall_tau") Double kendallTau) {
    }
}
