package org.trajeval.cli;

import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/** Refusals of command-line values the core does not check: one line naming the option (exit 2). */
final class UsageProblem {
    private UsageProblem() {
    }

    /**
     * @param option the option or argument ({@code --threads}, {@code -a})
     * @param detail what was expected
     * @param found what was given, or {@code null}
     * @return the exception to throw (an {@link InputException}: exit code 2)
     */
    static InputException of(String option, String detail, String found) {
        return new InputException(null, 0, option, InputProblem.INVALID_OPTION, detail, found);
    }

    /**
     * @param message the whole one-line message (what was given and what was expected)
     * @return the exception to throw (an {@link InputException}: exit code 2)
     */
    static InputException of(String message) {
        return new InputException(null, 0, null, InputProblem.INVALID_OPTION, message, null);
    }
}
