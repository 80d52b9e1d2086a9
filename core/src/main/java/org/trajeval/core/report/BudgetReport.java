package org.trajeval.core.report;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;

/**
 * The budget check of a suite report ({@code budgets}): every run's measured resources against the
 * manifest's budget, and each method's compliance.
 *
 * @param resources the resources table, relative to the manifest, or null when none was given
 * @param policy fail or warn: what a run over the budget is
 * @param unknownRuns runs without a resources row
 * @param methods per method, in manifest order
 * @param runs per run, in the order of the report's runs
 */
@JsonPropertyOrder({"resources", "policy", "unknown_runs", "methods", "runs"})
@JsonInclude(JsonInclude.Include.ALWAYS)
public record BudgetReport(@JsonProperty("resources") String resources, @JsonProperty("policy") String policy,
        @JsonProperty("unknown_runs") int unknownRuns, @JsonProperty("methods") List<MethodBudget> methods,
        @JsonProperty("runs") List<RunBudget> runs) {

    /**
     * @param method method name
     * @param runs its runs
     * @param within runs within the budget
     * @param over runs over it
     * @param unknown runs without a resources row
     * @param compliance within / (within + over), null when no run is known
     */
    @JsonPropertyOrder({"method", "runs", "within", "over", "unknown", "compliance"})
    public record MethodBudget(@JsonProperty("method") String method, @JsonProperty("runs") int runs,
            @JsonProperty("within") int within, @JsonProperty("over") int over, @JsonProperty("unknown") int unknown,
            @JsonProperty("compliance") Double compliance) {
    }

    /**
     * @param method method name
     * @param sequence sequence id
     * @param seed seed
     * @param status within, over or unknown
     * @param wallTimeS measured wall time (s)
     * @param peakMemoryMib measured peak memory (MiB)
     * @param cpuTimeS measured CPU time (s), or null
     * @param device device the run used, or null
     * @param durationS the reference's duration (s), null for frame-indexed references
     * @param realTimeFactor achieved real-time factor duration / wall time, or null
     * @param violations one line per exceeded limit, with the figure and the limit
     */
    @JsonPropertyOrder({"method", "sequence", "seed", "status", "wall_time_s", "peak_memory_mib", "cpu_time_s",
        "device", "duration_s", "real_time_factor", "violations"})
    public record RunBudget(@JsonProperty("method") String method, @JsonProperty("sequence") String sequence,
            @JsonProperty("seed") long seed, @JsonProperty("status") String status,
            @JsonProperty("wall_time_s") Double wallTimeS, @JsonProperty("peak_memory_mib") Double peakMemoryMib,
            @JsonProperty("cpu_time_s") Double cpuTimeS, @JsonProperty("device") String device,
            @JsonProperty("duration_s") Double durationS, @JsonProperty("real_time_factor") Double realTimeFactor,
            @JsonProperty("violations") List<String> violations) {
    }
}
