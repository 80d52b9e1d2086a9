package org.trajeval.core.fuzz;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;
import org.trajeval.core.InputException;
import org.trajeval.core.protocol.ManifestParser;

/**
 * Coverage-guided fuzzing of the suite manifest parser: any text gives a manifest or an
 * {@link InputException}; any other exception (or error, such as a stack overflow on deep
 * nesting) is a bug. Corpus: {@code src/test/resources/org/trajeval/core/fuzz/ManifestFuzzTestInputs/parse/}.
 */
class ManifestFuzzTest {
    private final ManifestParser parser = new ManifestParser();

    @FuzzTest(maxDuration = "10m")
    void parse(FuzzedDataProvider data) {
        try {
            parser.parse(data.consumeRemainingAsString(), "fuzz.yaml");
        } catch (InputException expected) {
            // the documented refusal of a bad manifest
        }
    }
}
