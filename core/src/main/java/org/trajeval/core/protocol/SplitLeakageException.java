package org.trajeval.core.protocol;

import java.util.List;
import java.util.stream.Collectors;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/** The split table leaks (see {@link SplitLeakage}) and leakage was not allowed; the CLI exits with 3. */
public final class SplitLeakageException extends InputException {
    private static final long serialVersionUID = 1L;

    private final transient List<SplitLeakage> leaks;

    /**
     * @param source the manifest or split table
     * @param leaks the violations (at least one)
     */
    public SplitLeakageException(String source, List<SplitLeakage> leaks) {
        super(source, 0, "split", InputProblem.INVALID_CONFIGURATION,
                "split leakage (s(i) = s(j) must imply split(i) = split(j)): "
                        + leaks.stream().map(SplitLeakage::describe).collect(Collectors.joining("; "))
                        + "; fix the splits or pass --allow-leakage to run anyway (flagged in the report)", null);
        this.leaks = List.copyOf(leaks);
    }

    /** @return the violations */
    public List<SplitLeakage> leaks() {
        return leaks;
    }
}
