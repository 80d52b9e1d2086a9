package org.trajeval.spark;

import java.io.PrintWriter;
import org.trajeval.core.InputException;
import org.trajeval.core.Version;
import picocli.CommandLine;
import picocli.CommandLine.Command;

/**
 * {@code trajeval-spark}: the launcher's command and the {@code spark-submit} entry point
 * ({@code --class org.trajeval.spark.SparkJob}). Exit codes: 0 done (pairs that could not be
 * scored are rows with status failed, not an exit code); 1 internal error; 2 bad input or usage
 * (the pairs table, its columns, the job's options, an output folder that exists; a bad suite
 * manifest or reference); 3 split leakage in a suite (and --allow-leakage not given), as
 * {@code trajeval suite}.
 */
@Command(name = "trajeval-spark", mixinStandardHelpOptions = true, versionProvider = SparkJob.VersionProvider.class,
        subcommands = {ScoreCommand.class, SuiteCommand.class},
        description = "Scores trajectory pairs (score) and benchmark suites (suite) on Apache Spark (local mode "
                + "by default, or the cluster of --master / spark-submit), with the numbers of trajeval eval and "
                + "the report of trajeval suite.")
public final class SparkJob implements Runnable {
    /** Exit code of success. */
    public static final int OK = 0;
    /** Exit code of an internal error. */
    public static final int INTERNAL = 1;
    /** Exit code of bad input or usage. */
    public static final int BAD_INPUT = 2;
    /** Exit code of split leakage in a suite (as {@code trajeval suite}'s). */
    public static final int LEAKAGE = 3;

    @CommandLine.Spec
    CommandLine.Model.CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "a subcommand is required (score, suite)");
    }

    /** Runs the command line and exits with its code. */
    public static void main(String[] args) {
        int code = commandLine().execute(args);
        System.exit(code);
    }

    /** @return the command line with trajeval's error handling (one line on stderr, documented exit codes) */
    public static CommandLine commandLine() {
        CommandLine cl = new CommandLine(new SparkJob());
        cl.setExecutionExceptionHandler((ex, c, parsed) -> {
            PrintWriter err = c.getErr();
            if (ex instanceof org.trajeval.core.protocol.SplitLeakageException) {
                err.println("trajeval-spark: " + ex.getMessage());
                err.flush();
                return LEAKAGE;
            }
            if (ex instanceof InputException) {
                err.println("trajeval-spark: " + ex.getMessage());
                err.flush();
                return BAD_INPUT;
            }
            if (ex instanceof org.apache.spark.sql.AnalysisException a) {
                // Spark's refusal of the pairs table (path not found, not Parquet, ...)
                err.println("trajeval-spark: " + a.getSimpleMessage());
                err.flush();
                return BAD_INPUT;
            }
            err.println("trajeval-spark: internal error: " + ex);
            ex.printStackTrace(err);
            err.flush();
            return INTERNAL;
        });
        cl.setParameterExceptionHandler((ex, args) -> {
            PrintWriter err = ex.getCommandLine().getErr();
            err.println("trajeval-spark: " + ex.getMessage());
            err.println("Try '" + ex.getCommandLine().getCommandSpec().qualifiedName() + " --help' for usage.");
            err.flush();
            return BAD_INPUT;
        });
        return cl;
    }

    /** Prints the tool version. */
    static final class VersionProvider implements CommandLine.IVersionProvider {
        @Override
        public String[] getVersion() {
            return new String[] {"trajeval-spark " + Version.TOOL + " (Apache Spark " + org.apache.spark.package$.MODULE$
                    .SPARK_VERSION() + ")"};
        }
    }
}
