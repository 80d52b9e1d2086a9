package org.trajeval.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;

/** {@code trajeval eval REF EST}: scores one estimate against one reference. */
@Command(name = "eval", mixinStandardHelpOptions = true, description = "Scores one estimate against a reference.")
public final class EvalCommand implements Callable<Integer> {
    @Override
    public Integer call() {
        throw new UnsupportedOperationException("eval not yet implemented");
    }
}
