package org.trajeval.pipeline;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.PropertyNamingStrategies;
import com.fasterxml.jackson.databind.exc.UnrecognizedPropertyException;
import com.fasterxml.jackson.databind.node.ObjectNode;
import org.trajeval.core.io.StrictMappers;
import org.trajeval.core.io.TextFiles;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Builds a {@link PipelineConfig}: defaults, then the YAML file, then environment variables
 * ({@code TRAJEVAL_PIPELINE_} + the key path in upper case joined by '_'), then {@code key=value}
 * overrides from the command line (dotted key paths, e.g. {@code kafka.group_id=g1}).
 */
public final class ConfigLoader {
    /** Prefix of the environment variables that override settings. */
    public static final String ENV_PREFIX = "TRAJEVAL_PIPELINE_";

    private static final ObjectMapper YAML = StrictMappers.yaml()
            .setPropertyNamingStrategy(PropertyNamingStrategies.SNAKE_CASE)
            .enable(DeserializationFeature.FAIL_ON_UNKNOWN_PROPERTIES);

    /** Mappings whose keys are not fixed here (checked by the core settings table instead). */
    private static final java.util.Set<String> FREE_MAPPINGS = java.util.Set.of(PipelineConfig.Bags.METRICS_KEY);

    private ConfigLoader() {
    }

    /**
     * @param file YAML file, or {@code null}
     * @param env environment variables (System.getenv() in the launcher)
     * @param overrides dotted key = value pairs, applied last
     * @throws InputException naming the file and key on an unknown key or a bad value
     */
    public static PipelineConfig load(Path file, Map<String, String> env, Map<String, String> overrides) {
        ObjectNode tree = YAML.valueToTree(PipelineConfig.defaults());
        String source = file == null ? "configuration" : file.toString();
        if (file != null) {
            try {
                JsonNode fromFile = YAML.readTree(TextFiles.readUtf8(file, "configuration", 1L << 20));
                if (fromFile != null && !fromFile.isNull() && !fromFile.isMissingNode()) {
                    if (!fromFile.isObject()) {
                        throw new InputException(source, 0, null, InputProblem.INVALID_CONFIGURATION,
                                "the configuration must be a YAML mapping", null);
                    }
                    merge(tree, (ObjectNode) fromFile, "", source);
                }
            } catch (JsonProcessingException e) {
                throw new InputException(source, e.getLocation() == null ? 0 : e.getLocation().getLineNr(), null,
                        InputProblem.INVALID_CONFIGURATION, "the configuration must be valid YAML: " + e.getOriginalMessage(),
                        null, e);
            }
        }
        for (String key : leafKeys(tree, "")) {
            String var = ENV_PREFIX + key.replace('.', '_').toUpperCase(Locale.ROOT);
            if (env.containsKey(var)) {
                set(tree, key, env.get(var), var);
            }
        }
        for (Map.Entry<String, String> o : overrides.entrySet()) {
            set(tree, o.getKey(), o.getValue(), "--set " + o.getKey());
        }
        try {
            PipelineConfig config = YAML.treeToValue(tree, PipelineConfig.class);
            try {
                config.bagSettings(); // checked now, so a bad bare-bag setting stops the start (exit 2)
            } catch (InputException e) {
                throw new InputException(source, 0, e.column(), e.problem(), e.detail(), e.found(), e);
            }
            return config;
        } catch (UnrecognizedPropertyException e) {
            throw new InputException(source, 0, e.getPropertyName(), InputProblem.INVALID_CONFIGURATION,
                    "unknown key '" + e.getPropertyName() + "'", e.getPropertyName(), e);
        } catch (JsonProcessingException e) {
            throw new InputException(source, 0, null, InputProblem.INVALID_CONFIGURATION,
                    "bad value: " + e.getOriginalMessage(), null, e);
        }
    }

    private static void merge(ObjectNode into, ObjectNode from, String prefix, String source) {
        for (Iterator<Map.Entry<String, JsonNode>> it = from.properties().iterator(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> f = it.next();
            JsonNode existing = into.get(f.getKey());
            if (existing == null) {
                throw new InputException(source, 0, prefix + f.getKey(), InputProblem.INVALID_CONFIGURATION,
                        "unknown key '" + prefix + f.getKey() + "' (expected one of " + fieldNames(into) + ")",
                        f.getKey());
            }
            if (FREE_MAPPINGS.contains(prefix + f.getKey())) {
                if (!f.getValue().isObject()) {
                    throw new InputException(source, 0, prefix + f.getKey(), InputProblem.INVALID_CONFIGURATION,
                            prefix + f.getKey() + " must be a mapping of settings", f.getValue().toString());
                }
                into.set(f.getKey(), f.getValue());
            } else if (existing.isObject() && f.getValue().isObject()) {
                merge((ObjectNode) existing, (ObjectNode) f.getValue(), prefix + f.getKey() + ".", source);
            } else {
                into.set(f.getKey(), f.getValue());
            }
        }
    }

    private static String fieldNames(ObjectNode n) {
        List<String> names = new ArrayList<>();
        n.fieldNames().forEachRemaining(names::add);
        return String.join(", ", names);
    }

    private static List<String> leafKeys(ObjectNode n, String prefix) {
        List<String> keys = new ArrayList<>();
        n.properties().forEach(f -> {
            if (f.getValue().isObject()) {
                keys.addAll(leafKeys((ObjectNode) f.getValue(), prefix + f.getKey() + "."));
            } else {
                keys.add(prefix + f.getKey());
            }
        });
        return keys;
    }

    private static void set(ObjectNode tree, String dottedKey, String value, String origin) {
        String[] parts = dottedKey.split("\\.");
        ObjectNode node = tree;
        for (int i = 0; i < parts.length - 1; i++) {
            JsonNode child = node.get(parts[i]);
            if (child == null || !child.isObject()) {
                throw unknown(dottedKey, origin);
            }
            node = (ObjectNode) child;
        }
        String leaf = parts[parts.length - 1];
        boolean free = FREE_MAPPINGS.contains(dottedKey.substring(0, Math.max(0, dottedKey.lastIndexOf('.'))));
        if (!free && (!node.has(leaf) || node.get(leaf).isObject())) {
            throw unknown(dottedKey, origin);
        }
        node.put(leaf, value);
    }

    private static InputException unknown(String key, String origin) {
        return new InputException(origin, 0, key, InputProblem.INVALID_CONFIGURATION,
                "unknown configuration key '" + key + "'", key);
    }

    /** @return the configuration as YAML, in the file's own key names (for {@code config --show}) */
    public static String toYaml(PipelineConfig c) {
        try {
            return YAML.writeValueAsString(c);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException("could not write the configuration as YAML", e);
        }
    }
}
