package org.trajeval.core.report;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;

/**
 * The methods' table restricted to the sequences of one value of a description field
 * ({@code slices}: domain, environment, modality, ground_truth).
 *
 * @param dimension domain, environment, modality or ground_truth
 * @param value the field's value
 * @param sequences evaluated sequences with that value
 * @param methods per method, the summary over those sequences only (as in {@code methods})
 */
@JsonPropertyOrder({"dimension", "value", "sequences", "methods"})
@JsonInclude(JsonInclude.Include.ALWAYS)
public record SliceReport(@JsonProperty("dimension") String dimension, @JsonProperty("value") String value,
        @JsonProperty("sequences") List<String> sequences,
        @JsonProperty("methods") List<SuiteReport.MethodSummary> methods) {
}
