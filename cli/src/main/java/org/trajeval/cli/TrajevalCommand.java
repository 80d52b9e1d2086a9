package org.trajeval.cli;

import java.io.PrintWriter;
import org.trajeval.core.InputException;
import org.trajeval.core.InputText;
import org.trajeval.core.Version;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;

/** The {@code trajeval} command: scores trajectories and benchmark suites. */
@Command(name = "trajeval", mixinStandardHelpOptions = true, versionProvider = TrajevalCommand.VersionProvider.class,
        description = "Scores robot trajectories against ground truth (ATE, RPE, drift) and runs benchmark suites.",
        subcommands = {EvalCommand.class, ResCommand.class, SuiteCommand.class, CompareCommand.class, SplitsCommand.class,
            DemoCommand.class, TopicsCommand.class, ConvertCommand.class, DbCommand.class, GateCommand.class,
            TrendCommand.class},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success", "1:internal error (a bug; rerun with --verbose and report it)",
            "2:bad input or usage (the message names file, line and what was expected)",
            "3:leakage found (splits check)", "5:regression found (gate)"})
public final class TrajevalCommand implements Runnable {

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "a subcommand is required");
    }

    /** Entry point of the launcher. */
    public static void main(String[] args) {
        EvalWarmUp.startFor(args);
        System.exit(newCommandLine(args).execute(args));
    }

    /** @return the configured command line (used by tests with their own out/err writers) */
    public static CommandLine newCommandLine() {
        CommandLine cl = new CommandLine(new TrajevalCommand());
        SettingOptions.addTo(cl.getSubcommands().get("eval").getCommandSpec());
        return configured(cl);
    }

    /**
     * The command line for {@code args}: for {@code trajeval eval ...} one that knows only
     * {@code eval}, otherwise {@link #newCommandLine()}. picocli builds the model of every
     * subcommand it is given by reflection (their options, converters, enum types: about 0.1 s of
     * a cold start); an eval parses, prints help and errors exactly as with the whole command.
     */
    public static CommandLine newCommandLine(String[] args) {
        if (args.length == 0 || !args[0].equals("eval")) {
            return newCommandLine();
        }
        CommandLine cl = new CommandLine(CommandSpec.wrapWithoutInspection(new TrajevalCommand()).name("trajeval"));
        cl.addSubcommand("eval", new EvalCommand());
        SettingOptions.addTo(cl.getSubcommands().get("eval").getCommandSpec());
        return configured(cl);
    }

    private static CommandLine configured(CommandLine cl) {
        cl.setExecutionExceptionHandler(new ErrorHandler());
        cl.setParameterExceptionHandler(TrajevalCommand::usageError);
        cl.setExitCodeExceptionMapper(t -> t instanceof InputException ? ExitCodes.BAD_INPUT : ExitCodes.INTERNAL);
        return cl;
    }

    private static int usageError(CommandLine.ParameterException ex, String[] args) {
        PrintWriter err = ex.getCommandLine().getErr();
        err.println("trajeval: " + InputText.escape(ex.getMessage()));
        err.println("Try '" + ex.getCommandLine().getCommandSpec().qualifiedName() + " --help' for usage.");
        err.flush();
        return ExitCodes.BAD_INPUT;
    }

    /** Maps exceptions to one line on stderr and a documented exit code; stack trace only with --verbose. */
    static final class ErrorHandler implements CommandLine.IExecutionExceptionHandler {
        @Override
        public int handleExecutionException(Exception ex, CommandLine cl, CommandLine.ParseResult parsed) {
            PrintWriter err = cl.getErr();
            boolean verbose = isVerbose(parsed);
            // bad input is an InputException (the file, line or option it names) or a file that cannot be
            // read or written; anything else, IllegalArgumentException included, is a bug of ours
            if (ex instanceof InputException || ex instanceof java.io.UncheckedIOException
                    || ex instanceof org.trajeval.store.StoreException) {
                err.println("trajeval: " + InputText.escape(ex.getMessage()));
                if (verbose) {
                    ex.printStackTrace(err);
                }
                err.flush();
                return ExitCodes.BAD_INPUT;
            }
            err.println("trajeval: internal error: " + InputText.escape(String.valueOf(ex)));
            if (verbose) {
                ex.printStackTrace(err);
            } else {
                err.println("Rerun with --verbose for the stack trace, and please report it.");
            }
            err.flush();
            return ExitCodes.INTERNAL;
        }

        private static boolean isVerbose(CommandLine.ParseResult parsed) {
            for (CommandLine.ParseResult p = parsed; p != null; p = p.subcommand()) {
                if (p.hasMatchedOption("--verbose")) {
                    return true;
                }
            }
            return false;
        }
    }

    /** Prints the tool version. */
    static final class VersionProvider implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            return new String[] {"trajeval " + Version.TOOL};
        }
    }
}
