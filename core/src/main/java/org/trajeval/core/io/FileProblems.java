package org.trajeval.core.io;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.NoSuchFileException;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/** The refusals that concern a whole file rather than one field: unreadable, empty, too large. */
final class FileProblems {
    /** Command-line option that raises the byte limit. */
    static final String MAX_BYTES_OPTION = "--max-file-size";
    /** Command-line option that raises the pose limit. */
    static final String MAX_POSES_OPTION = "--max-poses";

    private FileProblems() {
    }

    static InputException unreadable(String source, Exception e) {
        String why;
        if (e instanceof NoSuchFileException || e instanceof java.io.FileNotFoundException) {
            why = "the file does not exist";
        } else if (e instanceof AccessDeniedException || e instanceof SecurityException) {
            why = "the file may not be read (permission denied)";
        } else if (e instanceof IOException && e.getMessage() != null && e.getMessage().contains("directory")) {
            why = "this is a directory, not a file";
        } else {
            why = "the file cannot be read (" + e.getClass().getSimpleName()
                    + (e.getMessage() == null ? "" : ": " + e.getMessage()) + ")";
        }
        return new InputException(source, 0, null, InputProblem.UNREADABLE, why, null, e);
    }

    static InputException tooManyBytes(String source, long bytes, long maxBytes) {
        return new InputException(source, 0, null, InputProblem.TOO_LARGE,
                "the file must be at most " + maxBytes + " bytes (raise the limit with " + MAX_BYTES_OPTION
                        + "), it has " + (bytes > maxBytes ? "more than " + maxBytes : bytes) + " bytes",
                null);
    }

    static InputException tooManyPoses(String source, long line, long maxPoses) {
        return new InputException(source, line, null, InputProblem.TOO_LARGE,
                "a trajectory may hold at most " + maxPoses + " poses (raise the limit with " + MAX_POSES_OPTION
                        + "); this line would be pose " + (maxPoses + 1),
                null);
    }

    static InputException empty(String source, String what) {
        return new InputException(source, 0, null, InputProblem.EMPTY,
                "the file must hold at least one pose; " + what, null);
    }
}
