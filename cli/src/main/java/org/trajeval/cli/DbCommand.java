package org.trajeval.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.trajeval.store.Labels;
import org.trajeval.store.ReportImport;
import org.trajeval.store.ResultsStore;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code trajeval db}: the results store's own commands. */
@Command(name = "db", mixinStandardHelpOptions = true,
        description = "The results store (SQLite file or PostgreSQL): import report folders, show what it holds.",
        subcommands = {DbCommand.Import.class, DbCommand.Info.class})
public final class DbCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        throw new picocli.CommandLine.ParameterException(spec.commandLine(), "a subcommand is required: import, info");
    }

    /** {@code trajeval db import DIR... --db URL [--tag KEY=VALUE]}. */
    @Command(name = "import", mixinStandardHelpOptions = true, sortOptions = false,
            description = {"Records every trajeval report under the folders (pipeline reports/RUN_ID.json, suite "
                + "report.json, eval --out reports) in the store. Results already stored are left as they are, so an import can be "
                + "repeated, run beside a live pipeline, or rebuild a lost store from the report files."},
            exitCodeListHeading = "%nExit codes:%n",
            exitCodeList = {"0:success", "1:internal error (a bug; rerun with --verbose)",
                "2:bad input (a broken report file, an unreachable store, a bad --tag)"})
    static final class Import implements Callable<Integer> {
        @Spec
        CommandSpec spec;

        @Parameters(arity = "1..*", paramLabel = "DIR", description = "Report folders or files.")
        List<Path> roots;

        @Mixin
        StoreOptions store = new StoreOptions();

        @Option(names = "--tag", paramLabel = "KEY=VALUE", description = {"Label every imported result "
            + "(repeatable): software_version, robot, site, route, method, seed fill their columns where the report "
            + "has none (an eval report has no method or seed of its own); other keys are free tags."})
        List<String> tags = new ArrayList<>();

        @Option(names = "--verbose", description = "Print stack traces of errors.")
        boolean verbose;

        @Override
        public Integer call() {
            if (!store.given()) {
                throw UsageProblem.of("db import: --db is required");
            }
            Labels labels = Labels.parse(tags, Labels.EVAL_COLUMNS);
            PrintWriter out = spec.commandLine().getOut();
            try (ResultsStore s = store.open()) {
                for (Path root : roots) {
                    ReportImport.Summary sum = ReportImport.run(s, root, labels);
                    out.printf("%s: %d report file(s), %d result(s), %d new, %d other JSON file(s) skipped%n", root,
                            sum.files(), sum.results(), sum.inserted(), sum.skipped());
                }
                out.printf("store %s: %d result(s)%n", s.location(), s.count());
            }
            out.flush();
            return ExitCodes.OK;
        }
    }

    /** {@code trajeval db info --db URL}. */
    @Command(name = "info", mixinStandardHelpOptions = true,
            description = "Creates or upgrades the store's schema and prints its location, schema version and size.",
            exitCodeListHeading = "%nExit codes:%n",
            exitCodeList = {"0:success", "1:internal error", "2:unreachable store or bad --db"})
    static final class Info implements Callable<Integer> {
        @Spec
        CommandSpec spec;

        @Mixin
        StoreOptions store = new StoreOptions();

        @Option(names = "--verbose", description = "Print stack traces of errors.")
        boolean verbose;

        @Override
        public Integer call() {
            if (!store.given()) {
                throw UsageProblem.of("db info: --db is required");
            }
            PrintWriter out = spec.commandLine().getOut();
            try (ResultsStore s = store.open()) {
                out.printf("store %s: schema version %d, %d result(s)%n", s.location(), ResultsStore.schemaVersion(),
                        s.count());
            }
            out.flush();
            return ExitCodes.OK;
        }
    }
}
