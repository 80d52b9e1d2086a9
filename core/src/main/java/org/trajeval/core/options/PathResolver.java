package org.trajeval.core.options;

import java.nio.file.Path;

/**
 * How a front end turns a path setting into a file: relative to the working folder (command
 * line), to the manifest's folder, inside a bundle; refusing what it must not read.
 */
@FunctionalInterface
public interface PathResolver {
    /**
     * @param text the path as written
     * @param where the setting's name in refusals ({@code --ref-times}, {@code ref_times})
     * @return the file
     * @throws org.trajeval.core.InputException when the path is not allowed
     */
    Path resolve(String text, String where);

    /** @return paths taken as written (the command line: relative to the working folder) */
    static PathResolver asWritten() {
        return (text, where) -> Path.of(text);
    }
}
