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
 * @param runVersion 1 for the first content of this run id, n for the n-th distinct content
 * @param contentSha256 SHA-256 over the run's identity, settings and both input files
 * @param referenceSha256 SHA-256 of the reference file's bytes
 * @param estimateSha256 SHA-256 of the estimate file's bytes
 * @param source where the run came from (bundle name or topic-partition@offset)
 * @param processedAt when the report was written (ISO-8601 UTC)
 * @param evaluation the evaluation report
 */
@JsonPropertyOrder({"schema", "schema_version", "tool_version", "run_id", "robot_id", "sequence", "method", "seed",
    "site", "software_version", "tags", "run_version", "content_sha256", "reference_sha256", "estimate_sha256", "source", "processed_at", "evaluation"})
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
        @JsonProperty("run_version") int runVersion,
        @JsonProperty("content_sha256") String contentSha256,
        @JsonProperty("reference_sha256") String referenceSha256,
        @JsonProperty("estimate_sha256") String estimateSha256,
        @JsonProperty("source") String source,
        @JsonProperty("processed_at") String processedAt,
        @JsonProperty("evaluation") EvaluationReport evaluation) {

    /** Name of the pipeline report schema. */
    public static final String SCHEMA = "trajeval.pipeline.run";
    /** Version of the pipeline report schema. */
    public static final int SCHEMA_VERSION = 1;
}
