package org.trajeval.core;

/** The tool's version, as written into every report. */
public final class Version {
    /** Version of trajeval, matching the Gradle project version. */
    public static final String TOOL = "0.1.0";

    private Version() {
    }
}
