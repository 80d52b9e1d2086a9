package org.trajeval.store;

import java.time.Instant;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.regex.Pattern;

/**
 * One run result as the store holds it: one row of {@code runs} plus its tags.
 *
 * @param resultSha256 the row key: SHA-256 (lower-case hex) of the result's identity, inputs,
 *     settings and labels; recording the same key again is a no-op
 * @param origin where it came from: {@code pipeline}, {@code suite} or {@code eval}
 * @param runId the pipeline's run id, or {@code method/sequence/seed} for a suite run
 * @param runVersion the pipeline report's version (1, 2, ...), or null
 * @param contentSha256 SHA-256 over the run's inputs (pipeline), or null
 * @param dataset the suite's benchmark name, or null
 * @param robot robot id, or null
 * @param site site, or null
 * @param route route or sequence id, or null
 * @param method method (estimator) name, or null
 * @param softwareVersion software version under test, or null
 * @param seed the method's seed, or null
 * @param recordedAt when the result was produced (pipeline: processed_at; suite: when recorded)
 * @param ok whether the run succeeded (a failed run has no metrics but a score of 0)
 * @param failureReason why it failed, or null
 * @param metrics metric columns ({@link StoredMetric#keys()}) to values; absent keys are NULL
 * @param source report file or other origin text, for people
 * @param tags free labels (key to value), stored in {@code run_tags}
 * @param description domain, scenario, taxonomy, factors and measured resources (schema v3)
 */
public record RunRecord(String resultSha256, String origin, String runId, Integer runVersion, String contentSha256,
        String dataset, String robot, String site, String route, String method, String softwareVersion, Long seed,
        Instant recordedAt, boolean ok, String failureReason, Map<String, Double> metrics, String source,
        Map<String, String> tags, RunDescription description) {

    /** A record without a description. */
    public RunRecord(String resultSha256, String origin, String runId, Integer runVersion, String contentSha256,
            String dataset, String robot, String site, String route, String method, String softwareVersion, Long seed,
            Instant recordedAt, boolean ok, String failureReason, Map<String, Double> metrics, String source,
            Map<String, String> tags) {
        this(resultSha256, origin, runId, runVersion, contentSha256, dataset, robot, site, route, method,
                softwareVersion, seed, recordedAt, ok, failureReason, metrics, source, tags, RunDescription.NONE);
    }
    private static final Pattern HEX64 = Pattern.compile("[0-9a-f]{64}");
    private static final Pattern TAG = Pattern.compile("[A-Za-z0-9_.-]{1,64}");

    /** @throws IllegalArgumentException on a malformed key, an unknown metric or a bad tag name */
    public RunRecord {
        if (resultSha256 == null || !HEX64.matcher(resultSha256).matches()) {
            throw new IllegalArgumentException("result key must be 64 lower-case hex digits, found " + resultSha256);
        }
        Objects.requireNonNull(origin, "origin");
        Objects.requireNonNull(recordedAt, "recordedAt");
        description = description == null ? RunDescription.NONE : description;
        metrics = Map.copyOf(metrics == null ? Map.of() : metrics);
        for (String k : metrics.keySet()) {
            if (!StoredMetric.keys().contains(k)) {
                throw new IllegalArgumentException("unknown metric column " + k);
            }
        }
        tags = Map.copyOf(new TreeMap<>(tags == null ? Map.of() : tags));
        for (Map.Entry<String, String> t : tags.entrySet()) {
            if (!TAG.matcher(t.getKey()).matches() || t.getValue() == null) {
                throw new IllegalArgumentException("tag names are 1-64 of A-Z a-z 0-9 . _ - with a value, found "
                        + t.getKey());
            }
        }
    }

    /** @return the metric's value, or NaN when absent */
    public double metric(String key) {
        Double v = metrics.get(key);
        return v == null ? Double.NaN : v;
    }
}
