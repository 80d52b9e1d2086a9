package org.trajeval.core.io;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.dataformat.yaml.YAMLFactory;

/**
 * The one place where the Jackson mappers that read our documents are made: suite manifests,
 * run.yaml, pipeline configuration, Kafka run events, reports read back. Every one refuses a key
 * that appears twice in one mapping ({@code JsonParser.Feature.STRICT_DUPLICATE_DETECTION}): a
 * second {@code score:} or {@code run_id} must not silently replace the first.
 */
public final class StrictMappers {
    private StrictMappers() {
    }

    /** @return a new JSON mapper that refuses duplicate keys */
    public static ObjectMapper json() {
        return new ObjectMapper().enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION);
    }

    /** @return a new YAML mapper that refuses duplicate keys */
    public static ObjectMapper yaml() {
        return new ObjectMapper(new YAMLFactory()).enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION);
    }
}
