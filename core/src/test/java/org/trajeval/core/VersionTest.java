package org.trajeval.core;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class VersionTest {
    @Test
    void versionIsSemantic() {
        assertTrue(Version.TOOL.matches("\\d+\\.\\d+\\.\\d+(-[0-9A-Za-z.-]+)?"), Version.TOOL);
    }

    @Test
    void versionIsTheBuildsProjectVersion() {
        // core/build.gradle passes the Gradle project version to the test JVM
        String built = System.getProperty("trajeval.version");
        assertNotNull(built, "run through gradle junitTest, which passes -Dtrajeval.version");
        assertEquals(built, Version.TOOL);
    }
}
