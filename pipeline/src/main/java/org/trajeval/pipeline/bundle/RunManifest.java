package org.trajeval.pipeline.bundle;

import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Iterator;
import java.util.Set;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.pipeline.MetricSettings;
import org.trajeval.pipeline.RunMetadata;

/**
 * A bundle's {@code run.yaml}:
 * <pre>
 * run_id: r0412          # required; names reports/r0412.json
 * robot_id: bot-3
 * sequence: warehouse-a
 * method: orb-slam3
 * seed: 7
 * reference: truth.csv   # required, relative to the bundle
 * estimate: estimate.csv # required, relative to the bundle
 * metrics:               # optional: convention, alignment, association, max_diff_s, rpe_delta, rpe_unit
 *   alignment: se2
 * </pre>
 * Unknown keys are refused (a typo must not silently change a metric).
 *
 * @param metadata the run's identity
 * @param reference the reference path as written
 * @param estimate the estimate path as written
 * @param settings the metric settings
 */
public record RunManifest(RunMetadata metadata, String reference, String estimate, MetricSettings settings) {
    /** Name of the manifest file in a bundle. */
    public static final String FILE_NAME = "run.yaml";

    private static final ObjectMapper YAML = org.trajeval.core.io.StrictMappers.yaml();
    private static final Set<String> KEYS = Set.of("run_id", "robot_id", "sequence", "method", "seed", "reference",
            "estimate", "metrics");
    private static final Set<String> METRIC_KEYS = Set.of("convention", "alignment", "association", "max_diff_s",
            "rpe_delta", "rpe_unit");

    /**
     * Reads and checks a manifest file.
     *
     * @param file the run.yaml
     * @param source how to name it in messages
     * @param maxBytes largest accepted size (bytes)
     * @throws InputException naming the field and what was expected
     */
    public static RunManifest read(Path file, String source, long maxBytes) {
        SafePaths.requireRegularFile(file, source, FILE_NAME, FILE_NAME, maxBytes);
        JsonNode root;
        try {
            root = YAML.readTree(org.trajeval.core.io.TextFiles.readUtf8(file, FILE_NAME, maxBytes));
        } catch (JsonProcessingException e) {
            JsonLocation loc = e.getLocation();
            throw new InputException(source, loc == null ? 0 : Math.max(0, loc.getLineNr()), null,
                    InputProblem.INVALID_CONFIGURATION, "run.yaml must be valid YAML: " + e.getOriginalMessage(),
                    null, e);
        }
        return parse(root, source);
    }

    /** @return the manifest in a parsed YAML or JSON tree (also used for Kafka run events) */
    static RunManifest parse(JsonNode root, String source) {
        if (root == null || !root.isObject()) {
            throw new InputException(source, 0, null, InputProblem.INVALID_CONFIGURATION,
                    "run.yaml must be a mapping of run_id, reference, estimate, ...", null);
        }
        requireKnown(root, KEYS, "", source);
        RunMetadata metadata;
        try {
            metadata = new RunMetadata(text(root, "run_id", source, true), text(root, "robot_id", source, false),
                    text(root, "sequence", source, false), text(root, "method", source, false), seed(root, source));
        } catch (InputException e) {
            throw new InputException(source, 0, e.column(), e.problem(), e.detail(), e.found(), e);
        }
        MetricSettings settings = MetricSettings.DEFAULTS;
        JsonNode m = root.get("metrics");
        if (m != null && !m.isNull()) {
            if (!m.isObject()) {
                throw new InputException(source, 0, "metrics", InputProblem.INVALID_CONFIGURATION,
                        "metrics must be a mapping", m.toString());
            }
            requireKnown(m, METRIC_KEYS, "metrics.", source);
            try {
                settings = new MetricSettings(text(m, "convention", source, false), text(m, "alignment", source, false),
                        text(m, "association", source, false), number(m, "max_diff_s", source),
                        number(m, "rpe_delta", source), text(m, "rpe_unit", source, false));
            } catch (InputException e) {
                throw new InputException(source, 0, e.column(), e.problem(), e.detail(), e.found(), e);
            }
        }
        return new RunManifest(metadata, text(root, "reference", source, true), text(root, "estimate", source, true),
                settings);
    }

    private static void requireKnown(JsonNode node, Set<String> keys, String prefix, String source) {
        for (Iterator<String> it = node.fieldNames(); it.hasNext(); ) {
            String k = it.next();
            if (!keys.contains(k)) {
                throw new InputException(source, 0, prefix + k, InputProblem.INVALID_CONFIGURATION,
                        "unknown key '" + prefix + k + "' (expected one of " + String.join(", ", new java.util.TreeSet<>(keys))
                                + ")", k);
            }
        }
    }

    private static String text(JsonNode node, String key, String source, boolean required) {
        JsonNode v = node.get(key);
        if (v == null || v.isNull()) {
            if (required) {
                throw new InputException(source, 0, key, InputProblem.INVALID_CONFIGURATION,
                        "missing required key '" + key + "'", null);
            }
            return null;
        }
        if (!v.isValueNode()) {
            throw new InputException(source, 0, key, InputProblem.INVALID_CONFIGURATION,
                    key + " must be a single value", v.toString());
        }
        return v.asText();
    }

    private static Long seed(JsonNode node, String source) {
        JsonNode v = node.get("seed");
        if (v == null || v.isNull()) {
            return null;
        }
        if (!v.canConvertToLong() || !v.isIntegralNumber()) {
            throw new InputException(source, 0, "seed", InputProblem.NOT_A_NUMBER, "seed must be a whole number",
                    v.asText());
        }
        return v.asLong();
    }

    private static Double number(JsonNode node, String key, String source) {
        JsonNode v = node.get(key);
        if (v == null || v.isNull()) {
            return null;
        }
        if (!v.isNumber()) {
            throw new InputException(source, 0, "metrics." + key, InputProblem.NOT_A_NUMBER,
                    "metrics." + key + " must be a number", v.asText());
        }
        return v.asDouble();
    }
}
