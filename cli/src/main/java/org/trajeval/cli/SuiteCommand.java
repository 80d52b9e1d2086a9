package org.trajeval.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.trajeval.core.protocol.SplitLeakageException;
import org.trajeval.core.protocol.SuiteRunner;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.store.Labels;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code trajeval suite MANIFEST --out DIR}: runs a benchmark suite and writes its reports. */
@Command(name = "suite", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Runs a benchmark suite: every (method, sequence, seed) of the manifest scored with the same "
            + "protocol, failures counted, split and seed hygiene checked, per-method statistics and paired "
            + "comparisons with intervals.",
            "Writes report.json, runs.csv, methods.csv, comparisons.csv, report.html and, with three or more "
                + "methods, one average-rank diagram per metric (ranks_METRIC.svg) into --out."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success", "1:internal error (a bug; rerun with --verbose)",
            "2:bad manifest or input (one line names the key path or file and what was expected)",
            "3:split leakage found (and --allow-leakage not given)"})
public final class SuiteCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "MANIFEST", description = "Suite manifest (YAML).")
    Path manifest;

    @Option(names = "--out", required = true, paramLabel = "DIR", description = "Report folder (created).")
    Path out;

    @picocli.CommandLine.Mixin
    StatisticsOptions stats = new StatisticsOptions();

    @Option(names = "--threads", paramLabel = "N", converter = BoundedOptions.Threads.class, description = "Worker threads (default: the number of cores).")
    Integer threads;

    @Option(names = "--allow-leakage", description = "Run despite split leakage; the report flags it.")
    boolean allowLeakage;

    @picocli.CommandLine.Mixin
    StoreOptions store = new StoreOptions();

    @Option(names = "--tag", paramLabel = "KEY=VALUE", description = {"With --db: label every run (repeatable), "
        + "e.g. software_version=2.4; software_version, robot, site fill their columns, other keys are free tags."})
    List<String> tags = new ArrayList<>();

    @Option(names = "--verbose", description = "Print stack traces of errors.")
    boolean verbose;

    @Override
    public Integer call() {
        PrintWriter o = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        long start = System.nanoTime();
        Labels labels = Labels.parse(tags);
        if (!tags.isEmpty() && !store.given()) {
            throw UsageProblem.of("--tag labels stored runs: it needs --db");
        }
        SuiteReport r;
        try {
            r = SuiteOutput.runAndWrite(manifest, out, stats.suite(allowLeakage),
                    threads == null ? Runtime.getRuntime().availableProcessors() : threads, err);
        } catch (SplitLeakageException e) {
            err.println("trajeval: " + e.getMessage());
            err.flush();
            return ExitCodes.LEAKAGE;
        }
        SuiteOutput.printSummary(r, o);
        if (store.given()) {
            SuiteOutput.record(r, out, labels, store, o);
        }
        o.printf(Locale.ROOT, "%nwrote %s (report.json, runs.csv, methods.csv, comparisons.csv, report.html) in %.1f s%n",
                out, (System.nanoTime() - start) / 1e9);
        o.flush();
        return ExitCodes.OK;
    }
}
