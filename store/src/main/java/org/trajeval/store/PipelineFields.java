package org.trajeval.store;

import java.util.Map;
import org.trajeval.core.report.EvaluationReport;

/**
 * What the store keeps of one pipeline report ({@code reports/RUN_ID.json}, schema
 * {@code trajeval.pipeline.run}): its labels, description and evaluation. Read from a report file
 * ({@link ReportRecords#fromPipeline(String, String, Labels)}) or taken from the report the pipeline
 * has just written (no re-read, no re-parse); both become one row through
 * {@link ReportRecords#fromPipeline(PipelineFields, String, Labels)}.
 *
 * @param runId {@code run_id}, or null
 * @param runVersion {@code run_version}, or null
 * @param contentSha256 {@code content_sha256} (required)
 * @param processedAt {@code processed_at}, ISO-8601 UTC (required)
 * @param robotId {@code robot_id}, or null
 * @param site {@code site}, or null
 * @param sequence {@code sequence}, or null
 * @param method {@code method}, or null
 * @param softwareVersion {@code software_version}, or null
 * @param seed {@code seed}, or null
 * @param tags {@code tags}, or null
 * @param factors {@code factors}, or null
 * @param wallTimeS {@code resources.wall_time_s} (s), or null
 * @param peakMemoryMib {@code resources.peak_memory_mib} (MiB), or null
 * @param domain {@code domain}, or null
 * @param scenario {@code scenario}, or null
 * @param simulator {@code simulator}, or null
 * @param environment {@code environment}, or null
 * @param modality {@code modality}, or null
 * @param groundTruth {@code ground_truth}, or null
 * @param evaluation {@code evaluation} (required)
 */
public record PipelineFields(String runId, Integer runVersion, String contentSha256, String processedAt,
        String robotId, String site, String sequence, String method, String softwareVersion, Long seed,
        Map<String, String> tags, Map<String, Double> factors, Double wallTimeS, Double peakMemoryMib,
        String domain, String scenario, String simulator, String environment, String modality, String groundTruth,
        EvaluationReport evaluation) {
}
