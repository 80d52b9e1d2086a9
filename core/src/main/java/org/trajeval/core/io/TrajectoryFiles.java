package org.trajeval.core.io;

import java.nio.file.Path;

/**
 * Reads the trajectory a pairs table names by text (a local path, or a URI of another file system
 * in {@code trajeval-spark}): how a front end that scores pairs reaches its files.
 */
@FunctionalInterface
public interface TrajectoryFiles {
    /** Local files: the text is a path, read by {@link TrajectoryReader#read(Path, ReadOptions)}. */
    TrajectoryFiles LOCAL = (name, options) -> TrajectoryReader.read(Path.of(name), options);

    /**
     * @param name the file as written in the table
     * @param options how to read it (the row's settings resolved)
     * @throws org.trajeval.core.InputException on any bad input, naming {@code name}
     */
    LoadedTrajectory read(String name, ReadOptions options);
}
