package org.trajeval.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import org.trajeval.core.protocol.SplitAssignment;
import org.trajeval.core.protocol.SplitLeakage;
import org.trajeval.core.protocol.SplitTable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code trajeval splits check SPLITS.csv}: the lesson's split-leakage check. */
@Command(name = "splits", mixinStandardHelpOptions = true, description = "Split tables: leakage checks.",
        subcommands = {SplitsCommand.Check.class})
public final class SplitsCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "a subcommand is required (check)");
    }

    /** {@code splits check}. */
    @Command(name = "check", mixinStandardHelpOptions = true,
            description = {"Checks a split table (CSV with header sequence_id, split and optionally session_id) for "
                + "leakage: every session must sit in one split (s(i) = s(j) => split(i) = split(j)), and no "
                + "sequence may be listed in two splits."},
            exitCodeListHeading = "%nExit codes:%n",
            exitCodeList = {"0:no leakage", "2:bad input (the table cannot be read)", "3:leakage found"})
    public static final class Check implements Callable<Integer> {
        @Spec
        CommandSpec spec;

        @Parameters(index = "0", paramLabel = "SPLITS.csv", description = "The split table.")
        Path table;

        @CommandLine.Option(names = "--verbose", description = "Print stack traces of errors.")
        boolean verbose;

        @Override
        public Integer call() {
            PrintWriter out = spec.commandLine().getOut();
            List<SplitAssignment> rows = SplitTable.read(table);
            List<SplitLeakage> leaks = SplitLeakage.find(rows);
            long sessions = rows.stream().map(SplitAssignment::sessionId).distinct().count();
            if (leaks.isEmpty()) {
                out.println("no leakage: " + rows.size() + " rows, " + sessions + " sessions");
                out.flush();
                return ExitCodes.OK;
            }
            out.println("LEAKAGE: " + leaks.size() + " violation(s) in " + table + " (" + rows.size() + " rows, "
                    + sessions + " sessions):");
            for (SplitLeakage l : leaks) {
                out.println("  " + l.describe());
            }
            out.flush();
            return ExitCodes.LEAKAGE;
        }
    }
}
