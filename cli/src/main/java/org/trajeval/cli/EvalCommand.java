package org.trajeval.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.List;
import java.util.Objects;
import java.util.concurrent.Callable;
import java.util.stream.Stream;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.OutputGuard;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.FileRole;
import org.trajeval.core.io.bag.BagSource;
import org.trajeval.core.io.bag.Bags;
import org.trajeval.core.options.FormatApplicability;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.Setting;
import org.trajeval.core.options.SettingText;
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
            "2:bad input or usage (one line names file, line and what was expected); with --db also a store "
                + "that cannot be opened or written",
            "4:--batch: some pairs could not be scored (failed rows of summary.csv, one stderr line each)"})
public final class EvalCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "REF", description = "Reference (ground-truth) trajectory "
            + "file, or a ROS bag (with --ref-topic, or written BAG:TOPIC).")
    Path reference;

    @Parameters(index = "1", arity = "0..1", paramLabel = "EST", description = "Estimated trajectory file, or a bag "
            + "(with --est-topic, or BAG:TOPIC). Left out when both topics come from the bag REF.")
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

    @picocli.CommandLine.Mixin
    PlotOptions plots = new PlotOptions();

    @Option(names = "--threads", paramLabel = "N", converter = BoundedOptions.Threads.class, description = "Threads for reading the two files at once and "
            + "for the element-wise passes of the evaluation; with --batch, pairs scored at once (default: ${DEFAULT-VALUE}; 1 does everything on "
            + "one thread). The numbers do not depend on it.", defaultValue = "2")
    int threads;

    @picocli.CommandLine.Mixin
    EvalRecording recording = new EvalRecording();

    @Option(names = "--verbose", description = "Print stack traces of errors.")
    boolean verbose;

    @Option(names = "--batch", paramLabel = "PAIRS.csv", description = "Score every pair of a CSV table in this one "
            + "process instead of REF EST: columns ref and est (paths relative to the table's folder), optional name "
            + "(the report's file name), columns named as settings (alignment, max_diff_s, ...) for that row; other "
            + "columns are copied to the summary. Needs --reports.")
    Path batch;

    @Option(names = "--reports", paramLabel = "DIR", description = "--batch: folder for one report per pair (NAME.json, "
            + "or line-NNNN.json) and summary.csv (the column names of a suite's runs.csv).")
    Path reports;

    @Override
    public Integer call() {
        List<SettingText> given = new ArrayList<>(SettingOptions.given(spec.commandLine().getParseResult()));
        if (batch != null) {
            if (reference != null || estimate != null || out != null || json || plots.wanted()) {
                throw UsageProblem.of("--batch", "--batch reads the pairs from its table: give no REF EST, --out, "
                        + "--json or plot options with it", null);
            }
            EvalWarmUp.awaitStarted();
            return EvalBatch.run(batch, reports, SettingValues.of(given, null), limits(), threads,
                    spec.commandLine().getOut(), spec.commandLine().getErr());
        }
        if (reference == null) {
            throw UsageProblem.of("REF", "REF is missing: give a reference and an estimate file (or --batch PAIRS.csv)",
                    null);
        }
        reference = bagTopic(reference, Setting.REF_TOPIC, "REF", given);
        if (estimate == null) {
            boolean oneBag = Bags.kind(reference) != null && given.stream().anyMatch(t -> t.key().equals(
                    Setting.EST_TOPIC.key()));
            if (!oneBag) {
                throw UsageProblem.of("EST", "EST is missing: give an estimate file, or a bag as REF with "
                        + "--est-topic (and --ref-topic)", null);
            }
            estimate = reference;
        }
        estimate = bagTopic(estimate, Setting.EST_TOPIC, "EST", given);
        SettingValues settings = SettingValues.of(given, null);
        org.trajeval.store.Labels labels = recording.labels();
        List<Path> inputs = Stream.of(reference, estimate, path(settings, Setting.REF_TIMES),
                path(settings, Setting.EST_TIMES)).filter(Objects::nonNull).toList();
        if (out != null) {
            OutputGuard.refuseInputs(out, "--out", inputs);
        }
        if (plots.plotDir != null) {
            OutputGuard.refuseFolderOfInputs(plots.plotDir, "--plot", inputs);
        }
        if (plots.seriesDir != null) {
            OutputGuard.refuseFolderOfInputs(plots.seriesDir, "--save-series", inputs);
        }
        MemoryBudget.check(reference, estimate, Runtime.getRuntime().maxMemory(), plots.wanted());
        if (inputs.stream().allMatch(Files::exists)) {
            // a refusal above, or the reader's for a missing file, is not held back by the warm-up
            EvalWarmUp.awaitStarted();
        }
        ReadOptions limits = limits();
        EvaluationReport report;
        List<String> notices;
        try (EvalThreads work = new EvalThreads(threads)) {
            LoadedTrajectory[] pair = work.both(
                    SettingsResolver.readOptions(settings, FileRole.REFERENCE, limits, PathResolver.asWritten()),
                    reference,
                    SettingsResolver.readOptions(settings, FileRole.ESTIMATE, limits, PathResolver.asWritten()),
                    estimate);
            LoadedTrajectory ref = pair[0];
            LoadedTrajectory est = pair[1];
            FormatApplicability.check(settings, ref, reference.toString(), est, estimate.toString());
            EvaluationOptions options = SettingsResolver.evaluationOptions(settings,
                    DataKind.of(ref.trajectory(), est.trajectory()));
            report = plots.wanted() ? EvalPlots.write(ref, est, options,
                    SettingsResolver.subTrajectoryLengthsM(settings), plots, spec.commandLine().getErr())
                    // the single eval's own pair, not used after the report: the reference's columns may serve as
                    // the evaluator's error arrays (the same report, 24 B per pose less at the peak)
                    : Evaluator.evaluateConsumingReference(ref, est, options, work.parallelism());
            notices = EvalNotices.of(report, options, (Integer) settings.get(Setting.N_TO_ALIGN));
        }
        PrintWriter err = spec.commandLine().getErr();
        for (String n : notices) {
            err.println("trajeval: warning: " + n);
        }
        err.flush();
        // JSON (and Jackson's start-up) only when asked for
        String jsonText = json || out != null || recording.wanted() ? ReportJson.toJson(report) : null;
        if (out != null) {
            ReportJson.writeAtomically(out, jsonText + "\n");
        }
        if (recording.wanted()) {
            recording.record(jsonText, out != null ? out.toString() : reference + " " + estimate, labels,
                    java.time.Clock.systemUTC(), err);
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

    private ReadOptions limits() {
        ReadOptions limits = ReadOptions.defaults();
        if (maxPoses != null || maxBytes != null) {
            limits = limits.withLimits(maxBytes != null ? maxBytes : limits.maxBytes(),
                    maxPoses != null ? maxPoses : limits.maxPoses());
        }
        return limits;
    }

    /**
     * A path written BAG:TOPIC becomes the bag and the topic setting (so a bag named either way is
     * read, and sets the default convention, the same way).
     */
    private static Path bagTopic(Path arg, Setting topic, String name, List<SettingText> given) {
        if (Files.exists(arg)) {
            return arg; // a file, or a bag named as is (its topic from the option)
        }
        BagSource bag = BagSource.resolve(arg.toString(), null);
        if (bag == null) {
            return arg; // the reader says what is wrong with it
        }
        if (given.stream().anyMatch(t -> t.key().equals(topic.key()))) {
            throw UsageProblem.of(topic.flag(), name + " names its topic (" + bag.topic() + ") and " + topic.flag()
                    + " names one too; give it once", bag.topic());
        }
        given.add(new SettingText(topic.key(), bag.topic(), name));
        return bag.path();
    }

    private static Path path(SettingValues s, Setting setting) {
        return s.has(setting) ? Path.of((String) s.get(setting)) : null;
    }
}
