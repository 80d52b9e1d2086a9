package org.trajeval.spark;

import java.nio.file.Files;
import java.nio.file.Path;
import org.apache.spark.sql.SparkSession;

/** The test session: local[2] on the loopback address, no UI; and the reference data folder. */
final class LocalSpark {
    private LocalSpark() {
    }

    static SparkSession start() {
        return SparkSessions.open("local[2]", "trajeval-spark-test");
    }

    /** @return ../shared/refdata (evo's test data, read in place); the tests fail, never skip, without it */
    static Path refdata() {
        Path p = Path.of(System.getProperty("trajeval.refdata", "../../shared/refdata"));
        if (!Files.isDirectory(p)) {
            throw new IllegalStateException("reference data folder " + p + " is missing (../shared/refdata)");
        }
        return p;
    }
}
