package org.trajeval.core;

import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import org.junit.jupiter.api.Assumptions;

/**
 * Where the real reference data is (../shared/refdata). Golden tests on it fail, not skip, when
 * it is missing: a green run must mean the parity was checked. Only the environment variable
 * {@value #SKIP_VARIABLE}=1 turns the failure into a skip, knowingly.
 */
public final class RefData {
    /** The environment variable that allows skipping the golden tests. */
    public static final String SKIP_VARIABLE = "TRAJEVAL_SKIP_REFDATA";

    private RefData() {
    }

    /** @return the refdata folder (system property trajeval.refdata, else ../../shared/refdata) */
    public static Path dir() {
        Path dir = Paths.get(System.getProperty("trajeval.refdata", "../../shared/refdata"));
        if (!Files.isRegularFile(dir.resolve("evo_reference.json"))) {
            if ("1".equals(System.getenv(SKIP_VARIABLE))) {
                Assumptions.abort("SKIPPED (" + SKIP_VARIABLE + "=1): reference data not found at "
                        + dir.toAbsolutePath());
            }
            fail("the reference data is not at " + dir.toAbsolutePath() + " (../shared/refdata); golden tests "
                    + "cannot run. Provide it, or set " + SKIP_VARIABLE + "=1 to skip them knowingly");
        }
        return dir;
    }
}
