package org.trajeval.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.FileRole;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code trajeval eval REF EST}: scores one estimate against one reference. */
@Command(name = "eval", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Scores an estimate trajectory against a reference (ground truth): time association, "
            + "alignment applied to whole poses, ATE, RPE and optional KITTI drift.",
            "Units: positions m, angles rad, times s; report keys name their unit (trans_m, rot_rad, max_gap_s).",
            "The evaluation settings below are the same, with the same names (as keys: --max-diff is max_diff_s), "
                + "in a suite manifest's metrics, a run.yaml and a Kafka run event."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success", "1:internal error (a bug; rerun with --verbose)",
            "2:bad input or usage (one line names file, line and what was expected)"})
public final class EvalCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "REF", description = "Reference (ground-truth) trajectory file.")
    Path reference;

    @Parameters(index = "1", paramLabel = "EST", description = "Estimated trajectory file.")
    Path estimate;

    @Option(names = "--max-poses", paramLabel = "N", description = "Refuse files with more poses "
            + "(default: 200000000).")
    Long maxPoses;

    @Option(names = "--max-file-size", paramLabel = "BYTES", description = "Refuse larger files "
            + "(default: 4 GiB).")
    Long maxBytes;

    @Option(names = "--json", description = "Print the report as one JSON object (schema trajeval.evaluation v1).")
    boolean json;

    @Option(names = "--out", paramLabel = "FILE", description = "Write the JSON report to FILE (atomically).")
    Path out;

    @Option(names = "--threads", paramLabel = "N", description = "Threads for reading the two files at once and "
            + "for the element-wise passes of the planar evaluation (default: ${DEFAULT-VALUE}; 1 does everything on "
            + "one thread). The numbers do not depend on it.", defaultValue = "2")
    int threads;

    @Option(names = "--verbose", description = "Print stack traces of errors.")
    boolean verbose;

    @Override
    public Integer call() {
        MemoryBudget.check(reference, estimate, Runtime.getRuntime().maxMemory());
        SettingValues settings = SettingValues.of(SettingOptions.given(spec.commandLine().getParseResult()), null);
        ReadOptions limits = ReadOptions.defaults();
        if (maxPoses != null || maxBytes != null) {
            limits = limits.withLimits(maxBytes != null ? maxBytes : limits.maxBytes(),
                    maxPoses != null ? maxPoses : limits.maxPoses());
        }
        EvaluationReport report;
        try (EvalThreads work = new EvalThreads(threads)) {
            LoadedTrajectory[] pair = work.both(
                    SettingsResolver.readOptions(settings, FileRole.REFERENCE, limits, PathResolver.asWritten()),
                    reference,
                    SettingsResolver.readOptions(settings, FileRole.ESTIMATE, limits, PathResolver.asWritten()),
                    estimate);
            LoadedTrajectory ref = pair[0];
            LoadedTrajectory est = pair[1];
            report = Evaluator.evaluate(ref, est, SettingsResolver.evaluationOptions(settings,
                    DataKind.of(ref.trajectory(), est.trajectory())), work.parallelism());
        }
        // JSON (and Jackson's start-up) only when asked for
        String jsonText = json || out != null ? ReportJson.toJson(report) : null;
        if (out != null) {
            ReportJson.writeAtomically(out, jsonText + "\n");
        }
        PrintWriter o = spec.commandLine().getOut();
        if (json && out == null) {
            o.println(jsonText);
        } else if (!json) {
            o.print(ReportTable.render(report));
        }
        o.flush();
        return ExitCodes.OK;
    }
}
