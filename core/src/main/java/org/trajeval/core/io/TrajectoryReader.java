package org.trajeval.core.io;

import java.nio.file.Path;

/** Reads trajectory files of every supported format. */
public final class TrajectoryReader {
    private TrajectoryReader() {
    }

    /**
     * Reads one file.
     *
     * @throws org.trajeval.core.InputException on any bad input, naming file, line, column and
     *     what was expected
     */
    public static LoadedTrajectory read(Path path, ReadOptions options) {
        throw new UnsupportedOperationException("readers not yet implemented");
    }
}
