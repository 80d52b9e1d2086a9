package org.trajeval.pipeline.kafka;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.apache.kafka.clients.producer.ProducerRecord;

/**
 * Builds report events: the value {@code {run_id, run_version, content_sha256, report_path,
 * source, report}} keyed by robot id (run id when the run has none), with headers
 * {@code trajeval.run_id}, {@code trajeval.content_sha256} and {@code trajeval.run_version}.
 * The pair (run id, content hash) identifies a report: consumers drop repeats by it (a report
 * event may be published more than once after broker faults, never less).
 */
public final class ReportEvents {
    /** Header: the run id. */
    public static final String RUN_ID = "trajeval.run_id";
    /** Header: the content hash of the run (SHA-256 hex). */
    public static final String CONTENT_HASH = "trajeval.content_sha256";
    /** Header: the report version. */
    public static final String RUN_VERSION = "trajeval.run_version";
    /** Header: present ("true") on events re-published from the ledger. */
    public static final String REPUBLISHED = "trajeval.republished";

    private static final ObjectMapper JSON = new ObjectMapper();

    private ReportEvents() {
    }

    /**
     * @param topic output topic
     * @param report the report file (read back and embedded)
     * @param source where the run came from
     * @param republished whether this event repeats one published before (from the ledger)
     * @return the report event
     * @throws UncheckedIOException when the report cannot be read back
     */
    public static ProducerRecord<String, String> of(String topic, Path report, String source, boolean republished) {
        JsonNode r;
        try {
            r = JSON.readTree(Files.readString(report));
        } catch (IOException e) {
            throw new UncheckedIOException("could not read back " + report + ": " + e.getMessage(), e);
        }
        String runId = r.path("run_id").asText();
        String hash = r.path("content_sha256").asText();
        int version = r.path("run_version").asInt();
        ObjectNode ev = JSON.createObjectNode();
        ev.put("run_id", runId);
        ev.put("run_version", version);
        ev.put("content_sha256", hash);
        ev.put("report_path", report.toString());
        ev.put("source", source);
        ev.set("report", r);
        String key = r.hasNonNull("robot_id") ? r.get("robot_id").asText() : runId;
        ProducerRecord<String, String> out = new ProducerRecord<>(topic, key, ev.toString());
        out.headers().add(RUN_ID, runId.getBytes(StandardCharsets.UTF_8));
        out.headers().add(CONTENT_HASH, hash.getBytes(StandardCharsets.UTF_8));
        out.headers().add(RUN_VERSION, String.valueOf(version).getBytes(StandardCharsets.UTF_8));
        if (republished) {
            out.headers().add(REPUBLISHED, "true".getBytes(StandardCharsets.UTF_8));
        }
        return out;
    }
}
