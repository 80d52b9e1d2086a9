package org.trajeval.spark;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.apache.spark.launcher.JavaModuleOptions;
import org.junit.jupiter.api.Test;

/** The module options of the launcher and the test JVMs (spark/build.gradle) are Spark's own list. */
class SparkModuleOptionsTest {
    @Test
    void theLaunchersJvmOptionsAreSparksJavaModuleOptionsWordForWord() {
        assertEquals(JavaModuleOptions.defaultModuleOptions(), System.getProperty("trajeval.sparkJvmOptions"),
                "spark/build.gradle's sparkJvmOptions must follow org.apache.spark.launcher.JavaModuleOptions "
                        + "of the Spark version in versions.gradle");
    }
}
