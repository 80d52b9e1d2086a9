package org.trajeval.core;

import java.util.Objects;

/**
 * Bad input that a person can fix: which source, which line and column, what was expected,
 * what was found. Unchecked; the CLI maps it to exit code 2 and prints {@link #getMessage()}
 * (one line) without a stack trace.
 *
 * <p>Example message: {@code runs/0412/estimate.csv:57: column 'yaw' must be a finite number (rad), found "nan"}.
 * The message is one printable line: control characters copied from the input are escaped
 * ({@link InputText#escape}); the typed fields keep the text as read.
 */
public class InputException extends RuntimeException {
    private static final long serialVersionUID = 1L;

    private final String source;
    private final long line;
    private final String column;
    private final InputProblem problem;
    private final String found;
    private final String detail;

    /**
     * @param source file path or other source name, may be {@code null} when not tied to a file
     * @param line 1-based line number, or 0 when the problem is not tied to a line
     * @param column column name or field, may be {@code null}
     * @param problem the kind of problem
     * @param detail what was expected and, where useful, what to do (no location, no "found")
     * @param found the offending text as read, may be {@code null}
     */
    public InputException(String source, long line, String column, InputProblem problem,
            String detail, String found) {
        this(source, line, column, problem, detail, found, null);
    }

    /** As {@link #InputException(String, long, String, InputProblem, String, String)}, with a cause. */
    public InputException(String source, long line, String column, InputProblem problem,
            String detail, String found, Throwable cause) {
        super(format(source, line, detail, found), cause);
        this.source = source;
        this.line = line;
        this.column = column;
        this.problem = Objects.requireNonNull(problem, "problem");
        this.detail = detail;
        this.found = found;
    }

    /**
     * A file that is not what the command reads (a report, a saved result, an archive): the message
     * names the file and what was expected.
     *
     * @param message the whole one-line message
     * @param cause the underlying failure, or {@code null}
     * @return the exception (bad input: exit code 2 in the command line)
     */
    public static InputException unreadable(String message, Throwable cause) {
        return new InputException(null, 0, null, InputProblem.UNREADABLE, message, null, cause);
    }

    /** As {@link #unreadable(String, Throwable)} without a cause. */
    public static InputException unreadable(String message) {
        return unreadable(message, null);
    }

    private static String format(String source, long line, String detail, String found) {
        StringBuilder sb = new StringBuilder();
        if (source != null) {
            sb.append(source);
            if (line > 0) {
                sb.append(':').append(line);
            }
            sb.append(": ");
        }
        sb.append(detail);
        if (found != null) {
            sb.append(", found \"").append(found.length() > 60 ? found.substring(0, 60) + "..." : found).append('"');
        }
        return InputText.escape(sb.toString());
    }

    /** @return the file or source name, or {@code null} */
    public String source() {
        return source;
    }

    /** @return the 1-based line number, or 0 when not tied to a line */
    public long line() {
        return line;
    }

    /** @return the column or field name, or {@code null} */
    public String column() {
        return column;
    }

    /** @return the kind of problem */
    public InputProblem problem() {
        return problem;
    }

    /** @return the offending text, or {@code null} */
    public String found() {
        return found;
    }

    /** @return what was expected (the message without location and found text) */
    public String detail() {
        return detail;
    }
}
