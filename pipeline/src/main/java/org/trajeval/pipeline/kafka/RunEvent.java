package org.trajeval.pipeline.kafka;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.Iterator;
import java.util.Set;
import java.util.regex.Pattern;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.pipeline.MetricSettings;
import org.trajeval.pipeline.RunMetadata;

/**
 * A run event from the input topic (JSON), either pointing at a bundle or carrying both
 * trajectories inline:
 * <pre>
 * {"run_id": "r0412", "robot_id": "bot-3", "bundle": "night-07/r0412.zip"}
 * {"run_id": "r0413", "robot_id": "bot-3", "sequence": "hall", "method": "orb", "seed": 1,
 *  "reference": {"file_name": "gt.csv", "data": "t,x,y,yaw\n0,0,0,0\n..."},
 *  "estimate":  {"file_name": "est.csv", "data": "..."},
 *  "metrics": {"alignment": "se2"}}
 * </pre>
 *
 * @param metadata run identity (for a bundle event: checked against the bundle's run.yaml)
 * @param bundle bundle location relative to the bundle base, or {@code null}
 * @param reference inline reference, or {@code null}
 * @param estimate inline estimate, or {@code null}
 * @param settings metric settings of an inline event
 */
public record RunEvent(RunMetadata metadata, String bundle, Inline reference, Inline estimate, MetricSettings settings) {
    private static final ObjectMapper JSON = org.trajeval.core.io.StrictMappers.json();
    private static final Set<String> KEYS = Set.of("run_id", "robot_id", "sequence", "method", "seed", "bundle",
            "reference", "estimate", "metrics");
    private static final Pattern FILE_NAME = Pattern.compile("[A-Za-z0-9_-][A-Za-z0-9._-]{0,100}");

    /**
     * An inline trajectory.
     *
     * @param fileName simple file name (the extension guides format detection), e.g. gt.csv, est.txt
     * @param data the file's text
     */
    public record Inline(String fileName, String data) {
    }

    /** @throws InputException naming the field when the event is malformed */
    public static RunEvent parse(String json, String source) {
        JsonNode root;
        try {
            root = json == null ? null : JSON.readTree(json);
        } catch (JsonProcessingException e) {
            throw new InputException(source, 0, null, InputProblem.INVALID_CONFIGURATION,
                    "a run event must be a JSON object: " + e.getOriginalMessage(), null, e);
        }
        if (root == null || !root.isObject()) {
            throw new InputException(source, 0, null, InputProblem.INVALID_CONFIGURATION,
                    "a run event must be a JSON object with run_id and bundle (or reference and estimate)",
                    json == null ? "null" : json.length() > 40 ? json.substring(0, 40) : json);
        }
        for (Iterator<String> it = root.fieldNames(); it.hasNext(); ) {
            String k = it.next();
            if (!KEYS.contains(k)) {
                throw new InputException(source, 0, k, InputProblem.INVALID_CONFIGURATION,
                        "unknown key '" + k + "' in the run event", k);
            }
        }
        RunMetadata metadata;
        try {
            metadata = new RunMetadata(text(root, "run_id"), text(root, "robot_id"), text(root, "sequence"),
                    text(root, "method"), root.hasNonNull("seed") ? root.get("seed").asLong() : null);
        } catch (InputException e) {
            throw new InputException(source, 0, e.column(), e.problem(), e.detail(), e.found(), e);
        }
        String bundle = text(root, "bundle");
        Inline ref = inline(root, "reference", source);
        Inline est = inline(root, "estimate", source);
        if ((bundle == null) == (ref == null || est == null)) {
            throw new InputException(source, 0, "bundle", InputProblem.INVALID_CONFIGURATION,
                    "a run event needs either bundle or both reference and estimate", null);
        }
        MetricSettings settings = MetricSettings.DEFAULTS;
        JsonNode m = root.get("metrics");
        if (m != null && m.isObject()) {
            try {
                settings = new MetricSettings(text(m, "convention"), text(m, "alignment"), text(m, "association"),
                        m.hasNonNull("max_diff_s") ? m.get("max_diff_s").asDouble() : null,
                        m.hasNonNull("rpe_delta") ? m.get("rpe_delta").asDouble() : null, text(m, "rpe_unit"));
            } catch (InputException e) {
                throw new InputException(source, 0, e.column(), e.problem(), e.detail(), e.found(), e);
            }
        }
        return new RunEvent(metadata, bundle, ref, est, settings);
    }

    private static Inline inline(JsonNode root, String key, String source) {
        JsonNode n = root.get(key);
        if (n == null || n.isNull()) {
            return null;
        }
        if (!n.isObject() || !n.hasNonNull("data") || !n.get("data").isTextual()) {
            throw new InputException(source, 0, key, InputProblem.INVALID_CONFIGURATION,
                    key + " must be an object {\"file_name\": ..., \"data\": \"<file text>\"}", n.toString());
        }
        String name = n.hasNonNull("file_name") ? n.get("file_name").asText() : key + ".csv";
        if (!FILE_NAME.matcher(name).matches()) {
            throw new InputException(source, 0, key + ".file_name", InputProblem.PATH_ESCAPES,
                    key + ".file_name must be a plain file name (A-Z a-z 0-9 . _ -)", name);
        }
        return new Inline(name, n.get("data").asText());
    }

    private static String text(JsonNode n, String key) {
        JsonNode v = n.get(key);
        return v == null || v.isNull() ? null : v.asText();
    }
}
