package org.trajeval.pipeline;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import org.trajeval.core.report.EvaluationReport;

/**
 * The report file of one run, {@code reports/RUN_ID.json}: run metadata around the unchanged
 * {@link EvaluationReport} (the one report model, nested under {@code evaluation}).
 *
 * @param schema always {@link #SCHEMA}
 * @param schemaVersion always {@link #SCHEMA_VERSION}
 * @param toolVersion trajeval version that wrote the report
 * @param runId run id
 * @param robotId robot id, or null
 * @param sequence sequence, or null
 * @param method method, or null
 * @param seed seed, or null
 * @param site site (run.yaml or event {@code site}), or null
 * @param softwareVersion version of the software under test ({@code software_version}), or null
 * @param tags free tags ({@code tags}), or null when none
 * @param domain sim or real (run.yaml or event {@code domain}), or null
 * @param simulator the simulator, or null
 * @param scenario the scenario, or null
 * @param factors controlled factor levels, or null when none
 * @param environment environment type, or null
 * @param modality sensing modality (words joined by '+'), or null
 * @param groundTruth ground-truth source, or null
 * @param resources measured wall time and memory, or null
 * @param runVersion 1 for the first content of this run id, n for the n-th distinct content
 * @param contentSha256 SHA-256 over the run's identity, settings and both input files
 * @param referenceSha256 SHA-256 of the reference file's bytes
 * @param estimateSha256 SHA-256 of the estimate file's bytes
 * @param source where the run came from (bundle name or topic-partition@offset)
 * @param processedAt when the report was written (ISO-8601 UTC)
 * @param evaluation the evaluation report
 */
@JsonPropertyOrder({"schema", "schema_version", "tool_version", "run_id", "robot_id", "sequence", "method", "seed",
    "site", "software_version", "tags", "domain", "simulator", "scenario", "factors", "environment", "modality",
    "ground_truth", "resources", "run_version", "content_sha256", "reference_sha256", "estimate_sha256", "source", "processed_at", "evaluation"})
@JsonInclude(JsonInclude.Include.NON_NULL)
public record PipelineReport(
        @JsonProperty("schema") String schema,
        @JsonProperty("schema_version") int schemaVersion,
        @JsonProperty("tool_version") String toolVersion,
        @JsonProperty("run_id") String runId,
        @JsonProperty("robot_id") String robotId,
        @JsonProperty("sequence") String sequence,
        @JsonProperty("method") String method,
        @JsonProperty("seed") Long seed,
        @JsonProperty("site") String site,
        @JsonProperty("software_version") String softwareVersion,
        @JsonProperty("tags") java.util.Map<String, String> tags,
        @JsonProperty("domain") String domain,
        @JsonProperty("simulator") String simulator,
        @JsonProperty("scenario") String scenario,
        @JsonProperty("factors") java.util.Map<String, Double> factors,
        @JsonProperty("environment") String environment,
        @JsonProperty("modality") String modality,
        @JsonProperty("ground_truth") String groundTruth,
        @JsonProperty("resources") Resources resources,
        @JsonProperty("run_version") int runVersion,
        @JsonProperty("content_sha256") String contentSha256,
        @JsonProperty("reference_sha256") String referenceSha256,
        @JsonProperty("estimate_sha256") String estimateSha256,
        @JsonProperty("source") String source,
        @JsonProperty("processed_at") String processedAt,
        @JsonProperty("evaluation") EvaluationReport evaluation) {

    /**
     * Measured resources of the run.
     *
     * @param wallTimeS wall time (s)
     * @param peakMemoryMib peak memory (MiB)
     * @param cpuTimeS CPU time (s), or null
     * @param device cpu or gpu, or null
     */
    @JsonPropertyOrder({"wall_time_s", "peak_memory_mib", "cpu_time_s", "device"})
    public record Resources(@JsonProperty("wall_time_s") double wallTimeS,
            @JsonProperty("peak_memory_mib") double peakMemoryMib, @JsonProperty("cpu_time_s") Double cpuTimeS,
            @JsonProperty("device") String device) {
    }

    /** Name of the pipeline report schema. */
    public static final String SCHEMA = "trajeval.pipeline.run";
    /** Version of the pipeline report schema. */
    public static final int SCHEMA_VERSION = 1;
}
