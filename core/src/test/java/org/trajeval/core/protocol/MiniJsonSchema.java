package org.trajeval.core.protocol;

import com.fasterxml.jackson.databind.JsonNode;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

/**
 * A small JSON Schema checker for the keywords docs/suite-report.schema.json uses: type, const,
 * enum, required, properties, additionalProperties, items, anyOf, $ref (to #/$defs), pattern.
 */
public final class MiniJsonSchema {
    private final JsonNode root;

    public MiniJsonSchema(JsonNode root) {
        this.root = root;
    }

    /** @return the violations, empty when the document conforms */
    public List<String> check(JsonNode doc) {
        List<String> out = new ArrayList<>();
        check(root, doc, "$", out);
        return out;
    }

    private void check(JsonNode schema, JsonNode v, String path, List<String> out) {
        if (schema.has("$ref")) {
            String ref = schema.get("$ref").asText();
            check(root.get("$defs").get(ref.substring("#/$defs/".length())), v, path, out);
            return;
        }
        if (schema.has("anyOf")) {
            for (JsonNode alt : schema.get("anyOf")) {
                List<String> sub = new ArrayList<>();
                check(alt, v, path, sub);
                if (sub.isEmpty()) {
                    return;
                }
            }
            out.add(path + ": matches no alternative of anyOf");
            return;
        }
        if (schema.has("const") && !schema.get("const").equals(v)) {
            out.add(path + ": expected " + schema.get("const") + ", found " + v);
        }
        if (schema.has("enum")) {
            boolean found = false;
            for (JsonNode e : schema.get("enum")) {
                found |= e.equals(v);
            }
            if (!found) {
                out.add(path + ": " + v + " not in " + schema.get("enum"));
            }
        }
        if (schema.has("type")) {
            List<String> types = new ArrayList<>();
            if (schema.get("type").isArray()) {
                schema.get("type").forEach(t -> types.add(t.asText()));
            } else {
                types.add(schema.get("type").asText());
            }
            if (types.stream().noneMatch(t -> is(t, v))) {
                out.add(path + ": expected type " + types + ", found " + v.getNodeType());
                return;
            }
        }
        if (schema.has("pattern") && v.isTextual() && !v.asText().matches(schema.get("pattern").asText())) {
            out.add(path + ": does not match " + schema.get("pattern"));
        }
        if (v.isObject()) {
            if (schema.has("required")) {
                for (JsonNode r : schema.get("required")) {
                    if (!v.has(r.asText())) {
                        out.add(path + ": missing required key " + r.asText());
                    }
                }
            }
            JsonNode props = schema.get("properties");
            JsonNode extra = schema.get("additionalProperties");
            Iterator<Map.Entry<String, JsonNode>> it = v.fields();
            while (it.hasNext()) {
                Map.Entry<String, JsonNode> e = it.next();
                if (props != null && props.has(e.getKey())) {
                    check(props.get(e.getKey()), e.getValue(), path + "." + e.getKey(), out);
                } else if (extra != null && extra.isBoolean() && !extra.asBoolean()) {
                    out.add(path + ": key " + e.getKey() + " is not in the schema");
                } else if (extra != null && extra.isObject()) {
                    check(extra, e.getValue(), path + "." + e.getKey(), out);
                }
            }
        }
        if (v.isArray() && schema.has("items")) {
            for (int i = 0; i < v.size(); i++) {
                check(schema.get("items"), v.get(i), path + "[" + i + "]", out);
            }
        }
    }

    private static boolean is(String type, JsonNode v) {
        return switch (type) {
            case "object" -> v.isObject();
            case "array" -> v.isArray();
            case "string" -> v.isTextual();
            case "integer" -> v.isIntegralNumber();
            case "number" -> v.isNumber();
            case "boolean" -> v.isBoolean();
            case "null" -> v.isNull();
            default -> false;
        };
    }
}
