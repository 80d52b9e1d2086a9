package org.trajeval.core;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class VersionTest {
    @Test
    void versionIsSemantic() {
        assertEquals(3, Version.TOOL.split("\\.").length);
    }
}
