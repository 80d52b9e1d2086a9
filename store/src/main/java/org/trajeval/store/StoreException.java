package org.trajeval.store;

/**
 * A results store that cannot be opened, migrated, read or written, or a request it cannot
 * answer. The message is one line naming the store (never a secret) and what to do.
 */
public final class StoreException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** What went wrong, for callers that map problems to exit codes or retries. */
    public enum Problem {
        /** The --db value or a credential setting is malformed or not allowed. */
        BAD_LOCATION,
        /** The database could not be reached or refused the connection. */
        UNAVAILABLE,
        /** The schema is newer than this tool, or an applied migration was changed. */
        SCHEMA,
        /** A query's arguments (selection, metric, slice) are not valid. */
        BAD_QUERY,
        /** A report file could not be read as a trajeval report. */
        BAD_REPORT
    }

    private final Problem problem;

    /**
     * @param problem the kind of problem
     * @param message one line for a person
     * @param cause the library exception, or null
     */
    public StoreException(Problem problem, String message, Throwable cause) {
        super(message, cause);
        this.problem = problem;
    }

    /** @return the kind of problem */
    public Problem problem() {
        return problem;
    }
}
