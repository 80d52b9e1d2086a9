package org.trajeval.core.report;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;
import java.util.Map;

/**
 * A report record with maps of text keys, shaped like the pipeline report's {@code tags} and
 * {@code factors} (RecordJsonTest; public and top-level, as RecordJson writes only such records).
 */
@JsonPropertyOrder({"tags", "factors", "none", "nested"})
@JsonInclude(JsonInclude.Include.NON_NULL)
public record MapsRecord(@JsonProperty("tags") Map<String, String> tags,
        @JsonProperty("factors") Map<String, Double> factors, @JsonProperty("none") Map<String, String> none,
        @JsonProperty("nested") Map<String, List<Long>> nested) {
}
