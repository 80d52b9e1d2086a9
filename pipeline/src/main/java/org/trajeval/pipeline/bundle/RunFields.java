package org.trajeval.pipeline.bundle;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.Iterator;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsTree;
import org.trajeval.pipeline.RunLabels;
import org.trajeval.pipeline.RunMetadata;

/**
 * The fields every run intake shares (a bundle's run.yaml and a Kafka run event), read the same
 * strict way: unknown keys refused with the known ones listed, identity fields single values,
 * the seed a whole number, {@code metrics} a mapping of the core settings table.
 */
public final class RunFields {
    private static final ObjectMapper TREE = new ObjectMapper();

    private RunFields() {
    }

    /** @throws InputException naming the first key not in {@code keys} */
    public static void requireKnown(JsonNode node, Set<String> keys, String prefix, String source) {
        for (Iterator<String> it = node.fieldNames(); it.hasNext(); ) {
            String k = it.next();
            if (!keys.contains(k)) {
                throw new InputException(source, 0, prefix + k, InputProblem.INVALID_CONFIGURATION,
                        "unknown key '" + prefix + k + "' (expected one of " + String.join(", ", new TreeSet<>(keys))
                                + ")", k);
            }
        }
    }

    /** @return the text of a single-value field, or {@code null} when absent and not required */
    public static String text(JsonNode node, String key, String source, boolean required) {
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

    /** The keys of {@link #metadata} and {@link #labels}, which every intake accepts. */
    public static final Set<String> IDENTITY_KEYS = identityKeys();

    private static Set<String> identityKeys() {
        Set<String> keys = new java.util.HashSet<>(Set.of("run_id", "robot_id", "sequence", "method", "seed", "site",
                "software_version", "tags", "resources"));
        keys.addAll(org.trajeval.core.options.RunField.keys());
        return Set.copyOf(keys);
    }

    /** @return {@link #IDENTITY_KEYS} and an intake's own keys: the keys it accepts */
    public static Set<String> keysWith(String... own) {
        Set<String> all = new java.util.HashSet<>(IDENTITY_KEYS);
        all.addAll(Set.of(own));
        return Set.copyOf(all);
    }

    /**
     * @return the run identity: run_id (required), robot_id, sequence, method, seed (a whole number),
     *     and the fleet labels site, software_version, tags
     */
    public static RunMetadata metadata(JsonNode root, String source) {
        try {
            Map<String, Object> tree = describes(root) ? asMap(root) : Map.of();
            return new RunMetadata(text(root, "run_id", source, true), text(root, "robot_id", source, false),
                    text(root, "sequence", source, false), text(root, "method", source, false), seed(root, source),
                    labels(root, source), org.trajeval.core.options.RunMetadata.parse(tree, "", source),
                    org.trajeval.core.options.RunResources.parse(tree.get("resources"), "resources", source));
        } catch (InputException e) {
            throw new InputException(source, 0, e.column(), e.problem(), e.detail(), e.found(), e);
        }
    }

    /** The keys {@link #metadata} reads through the data-binding tree: the run's description and resources. */
    private static final Set<String> DESCRIPTION_KEYS = descriptionKeys();

    private static Set<String> descriptionKeys() {
        Set<String> keys = new java.util.HashSet<>(org.trajeval.core.options.RunField.keys());
        keys.add("resources");
        return Set.copyOf(keys);
    }

    /**
     * @return whether {@code root} holds a key of the run's description or resources; without one, the
     *     description and resources parse from an empty mapping exactly as from the whole tree (they read
     *     only those keys), so most runs skip the tree's conversion to a map
     */
    private static boolean describes(JsonNode root) {
        if (!root.isObject()) {
            return false;
        }
        for (Iterator<String> it = root.fieldNames(); it.hasNext(); ) {
            if (DESCRIPTION_KEYS.contains(it.next())) {
                return true;
            }
        }
        return false;
    }

    @SuppressWarnings("unchecked")
    private static Map<String, Object> asMap(JsonNode node) {
        return TREE.convertValue(node, Map.class);
    }

    /** @return site, software_version and tags (a mapping of single values) */
    private static RunLabels labels(JsonNode root, String source) {
        Map<String, String> tags = new java.util.LinkedHashMap<>();
        JsonNode t = root.get("tags");
        if (t != null && !t.isNull()) {
            if (!t.isObject()) {
                throw new InputException(source, 0, "tags", InputProblem.INVALID_CONFIGURATION,
                        "tags must be a mapping of KEY: VALUE", t.toString());
            }
            for (Iterator<Map.Entry<String, JsonNode>> it = t.fields(); it.hasNext(); ) {
                Map.Entry<String, JsonNode> e = it.next();
                tags.put(e.getKey(), label(e.getValue(), "tags." + e.getKey(), source));
            }
        }
        return new RunLabels(label(root.get("site"), "site", source),
                label(root.get("software_version"), "software_version", source), tags);
    }

    /**
     * @return a label's text, or null when absent; a fractional number is refused, since YAML and
     *     JSON read {@code 2.10} as the number 2.1 and the version would silently change
     */
    private static String label(JsonNode v, String field, String source) {
        if (v == null || v.isNull()) {
            return null;
        }
        if (!v.isValueNode()) {
            throw new InputException(source, 0, field, InputProblem.INVALID_CONFIGURATION,
                    field + " must be a single value", v.toString());
        }
        if (v.isNumber() && !v.isIntegralNumber()) {
            throw new InputException(source, 0, field, InputProblem.INVALID_CONFIGURATION,
                    field + " must be text: quote it (\"2.10\"), a number loses trailing zeros", v.asText());
        }
        return v.asText();
    }

    /**
     * @return the run's {@code plot} switch (false when absent): draw {@code eval --plot}'s figures
     *     beside the report
     * @throws InputException when it is not true or false
     */
    public static boolean plot(JsonNode node, String source) {
        JsonNode v = node.get("plot");
        if (v == null || v.isNull()) {
            return false;
        }
        if (!v.isBoolean()) {
            throw new InputException(source, 0, "plot", InputProblem.INVALID_CONFIGURATION,
                    "'plot' must be true or false", v.asText());
        }
        return v.asBoolean();
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

    /**
     * @return the checked settings of {@code metrics} (every key of the core settings table;
     *     nested mappings as shorthand), or the defaults when absent
     * @throws InputException when metrics is not a mapping, or on any unknown key or bad value
     */
    public static SettingValues settings(JsonNode root, String source) {
        JsonNode m = root.get("metrics");
        if (m == null || m.isNull()) {
            return SettingValues.DEFAULTS;
        }
        if (!m.isObject()) {
            throw new InputException(source, 0, "metrics", InputProblem.INVALID_CONFIGURATION,
                    "metrics must be a mapping of settings", m.toString());
        }
        return SettingValues.of(SettingsTree.flatten(asMap(m), "metrics", source), source);
    }

    /**
     * @return a file a path setting names inside a bundle folder (no escape, no link, size limited)
     * @throws InputException PATH_ESCAPES, UNREADABLE or TOO_LARGE naming the setting
     */
    public static java.nio.file.Path fileInBundle(java.nio.file.Path folder, String text, String source, String where,
            long maxBytes) {
        return SafePaths.resolveFile(folder, text, source, where, maxBytes);
    }
}
