package org.trajeval.cli;

/** The documented exit codes of {@code trajeval}. */
public final class ExitCodes {
    /** Success. */
    public static final int OK = 0;
    /** Internal error (a bug): please report it with the --verbose output. */
    public static final int INTERNAL = 1;
    /** Bad input or usage: the message names the file, line and what was expected. */
    public static final int BAD_INPUT = 2;
    /** {@code splits check}: leakage found. */
    public static final int LEAKAGE = 3;
    /** {@code eval --batch}: some pairs could not be scored (each a failed row of summary.csv). */
    public static final int SOME_FAILED = 4;
    /** {@code gate}: a metric of the candidate regressed beyond its tolerance. */
    public static final int REGRESSION = 5;

    private ExitCodes() {
    }
}
