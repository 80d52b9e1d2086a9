package org.trajeval.core.report;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.annotation.JsonProperty;
import org.junit.jupiter.api.Test;

class ReportJsonFiniteTest {
    record Numbers(@JsonProperty("nan") double nan, @JsonProperty("inf") Double inf,
            @JsonProperty("finite") double finite) {
    }

    @Test
    void nonFiniteNumbersAreWrittenAsNullNeverAsStrings() {
        String json = ReportJson.toJson(new Numbers(Double.NaN, Double.NEGATIVE_INFINITY, 0.25))
                .replaceAll("\\s+", "");
        assertEquals("{\"nan\":null,\"inf\":null,\"finite\":0.25}", json);
    }
}
