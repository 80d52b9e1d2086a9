package org.trajeval.pipeline;

import java.io.File;
import java.util.Arrays;
import java.util.stream.Collectors;

/**
 * The class path of a child JVM that runs the service as its launcher does: the test runtime class
 * path without the tests' resources folder, whose {@code logback-test.xml} would otherwise replace
 * the service's own logging ({@link LogSetup}) in the child.
 */
public final class LauncherClasspath {
    private LauncherClasspath() {
    }

    /** @return the test runtime class path ({@code trajeval.testClasspath}) without {@code .../resources/test} */
    public static String withoutTestLogging() {
        String all = System.getProperty("trajeval.testClasspath", System.getProperty("java.class.path"));
        return Arrays.stream(all.split(File.pathSeparator))
                .filter(e -> !e.replace(File.separatorChar, '/').endsWith("/resources/test"))
                .collect(Collectors.joining(File.pathSeparator));
    }
}
