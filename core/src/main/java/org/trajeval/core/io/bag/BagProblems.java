package org.trajeval.core.io.bag;

import java.io.IOException;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/** The refusals of the bag readers, one factory per kind; every message names the file and the byte offset. */
final class BagProblems {
    private BagProblems() {
    }

    /** @return a refusal for bytes that contradict the container's structure */
    static InputException corrupt(String source, long offset, String what) {
        return new InputException(source, 0, offset >= 0 ? "byte " + offset : null, InputProblem.CORRUPT_BAG,
                (offset >= 0 ? "at byte " + offset + ": " : "") + what, null);
    }

    /** @return a refusal for a length field that claims more bytes than remain (or than the limit) */
    static InputException length(String source, long offset, String field, long claimed, long remaining) {
        return corrupt(source, offset, field + " claims " + Long.toUnsignedString(claimed) + " bytes but only "
                + remaining + " remain; the file is truncated or corrupt");
    }

    /** @return a refusal for a feature trajeval does not read */
    static InputException unsupported(String source, String what, String found) {
        return new InputException(source, 0, null, InputProblem.UNSUPPORTED_BAG_FEATURE, what, found);
    }

    /** @return a refusal for a bag that cannot be read on this machine (what: one line, the reason and its fix) */
    static InputException unreadable(String source, String what, Throwable cause) {
        return new InputException(source, 0, null, InputProblem.UNREADABLE, what, null, cause);
    }

    /** @return a refusal for an I/O failure while reading the bag */
    static InputException io(String source, IOException e) {
        return new InputException(source, 0, null, InputProblem.UNREADABLE, "the file cannot be read ("
                + e.getClass().getSimpleName() + (e.getMessage() == null ? "" : ": " + e.getMessage()) + ")", null, e);
    }
}
