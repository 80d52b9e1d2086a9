package org.trajeval.core;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.Properties;

/**
 * The tool's version, as written into every report and printed by {@code --version}. It comes
 * from one place, the project version in the root {@code build.gradle}, which the build copies
 * into the resource {@code org/trajeval/core/version.properties}; the published artefacts and
 * the executable jars carry the same version in their names.
 */
public final class Version {
    /** Version of trajeval (semantic versioning: MAJOR.MINOR.PATCH), from the build. */
    public static final String TOOL = load();

    private Version() {
    }

    private static String load() {
        try (InputStream in = Version.class.getResourceAsStream("version.properties")) {
            if (in == null) {
                throw new IllegalStateException("org/trajeval/core/version.properties is missing from the class path:"
                        + " the core jar was not built by its Gradle build");
            }
            Properties p = new Properties();
            p.load(in);
            String v = p.getProperty("version", "");
            if (!v.matches("\\d+\\.\\d+\\.\\d+(-[0-9A-Za-z.-]+)?")) {
                throw new IllegalStateException("org/trajeval/core/version.properties holds no version (found \""
                        + v + "\"): the resource was not expanded by the build");
            }
            return v;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read org/trajeval/core/version.properties", e);
        }
    }
}
