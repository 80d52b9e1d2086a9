package org.trajeval.core.protocol;

import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.FileRole;
import org.trajeval.core.options.SettingText;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.SequencePlot;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.RunEntry;
import org.trajeval.core.traj.Trajectory;

/**
 * The per-run step of a suite: one {@link RunTask} of a manifest in, one {@link RunResult} out. It
 * reads the files the manifest names (relative to its folder, which they may not leave), resolves
 * each run's settings (suite, then sequence, then method) and scores with the engine. It holds no
 * state between runs, so any thread or any worker of a cluster that can read the manifest's folder
 * gives the same result for the same task.
 */
public final class RunScorer {
    /** Most points drawn per trace in the HTML plots. */
    static final int MAX_PLOT_POINTS = 1500;

    private final RunEngine engine;
    private final SuiteManifest m;
    private final String source;
    private final Path base;

    /**
     * @param engine reader and evaluator
     * @param manifest the parsed manifest
     * @param manifestFile where it was read from (its folder is the base of every path in it)
     */
    public RunScorer(RunEngine engine, SuiteManifest manifest, Path manifestFile) {
        this.engine = Objects.requireNonNull(engine, "engine");
        this.m = Objects.requireNonNull(manifest, "manifest");
        this.source = manifestFile.toString();
        this.base = manifestFile.toAbsolutePath().normalize().getParent();
    }

    /**
     * The scorer of a worker: parses the manifest at {@code manifestFile} and checks it is the one the
     * plan was made from.
     *
     * @param engine reader and evaluator
     * @param manifestFile the manifest, by the path the plan used (a folder every worker sees)
     * @param sha256 the manifest's SHA-256 when the plan was made ({@link SuitePlan#manifestSha256()})
     * @return the scorer
     * @throws InputException when the manifest cannot be read or has changed since the plan was made
     */
    public static RunScorer of(RunEngine engine, Path manifestFile, String sha256) {
        String now = ManifestPaths.sha256(manifestFile);
        if (!now.equals(sha256)) {
            throw new InputException(manifestFile.toString(), 0, null, InputProblem.INVALID_CONFIGURATION,
                    "the manifest changed while the suite ran (SHA-256 " + sha256 + " when planned); rerun the suite",
                    now);
        }
        return new RunScorer(engine, new ManifestParser().read(manifestFile), manifestFile);
    }

    /**
     * Reads the reference of a sequence with the sequence's settings (the suite's {@code metrics}, then
     * the sequence's), named as the manifest wrote its path.
     *
     * @throws InputException when the sequence is unknown, its reference leaves the manifest's folder,
     *     does not exist or cannot be read
     */
    public LoadedTrajectory reference(String sequenceId) {
        SequenceSpec s = sequence(sequenceId);
        Path file = referenceFile(m.sequences().indexOf(s));
        return ManifestPaths.renamed(engine.read(file, SettingsResolver.readOptions(m.metrics().with(s.settings(),
                source), FileRole.REFERENCE, ReadOptions.defaults(), ManifestPaths.paths(base, source))),
                s.reference());
    }

    /**
     * @param i index of the sequence in the manifest
     * @return its reference file, resolved
     * @throws InputException when it leaves the manifest's folder or does not exist
     */
    Path referenceFile(int i) {
        SequenceSpec s = m.sequences().get(i);
        Path file = ManifestPaths.inside(base, s.reference(), source, "sequences[" + i + "].reference");
        if (!Files.isRegularFile(file)) {
            throw new InputException(source, 0, "sequences[" + i + "].reference", InputProblem.UNREADABLE,
                    "'sequences[" + i + "].reference': reference file does not exist", s.reference());
        }
        return file;
    }

    private MethodSpec method(String name) {
        for (MethodSpec ms : m.methods()) {
            if (ms.name().equals(name)) {
                return ms;
            }
        }
        throw new InputException(source, 0, "methods", InputProblem.INVALID_CONFIGURATION,
                "the manifest has no method '" + name + "'", name);
    }

    private SequenceSpec sequence(String id) {
        SequenceSpec s = m.sequence(id);
        if (s == null) {
            throw new InputException(source, 0, "sequences", InputProblem.INVALID_CONFIGURATION,
                    "the manifest has no sequence '" + id + "'", id);
        }
        return s;
    }

    /**
     * The settings of one run: the suite's {@code metrics}, then the sequence's settings, then the
     * method's (placeholders in path settings filled in).
     */
    static SettingValues runSettings(SuiteManifest m, MethodSpec ms, SequenceSpec s, long seed, String source) {
        List<SettingText> own = new ArrayList<>();
        for (SettingText t : ms.settings()) {
            own.add(new SettingText(t.key(), t.text() == null ? null : ms.fill(t.text(), s.id(), seed), t.where()));
        }
        return m.metrics().with(s.settings(), source).with(own, source);
    }

    /**
     * Scores one run: reads the estimate, evaluates it against the reference with the run's settings
     * and judges it by the manifest's failure definition. A missing or unreadable estimate, a pair the
     * evaluation refuses and a judged failure are results with status {@code failed} and their reason,
     * never exceptions.
     *
     * @param task the run
     * @param reference the sequence's reference ({@link #reference(String)})
     * @return the run's result
     * @throws InputException when the task names a method or sequence the manifest lacks, or an estimate
     *     path that leaves the manifest's folder
     */
    public RunResult score(RunTask task, LoadedTrajectory reference) {
        MethodSpec ms = method(task.method());
        SequenceSpec s = sequence(task.sequence());
        long seed = task.seed();
        String rel = task.estimate();
        Path file = ManifestPaths.inside(base, rel, source, "methods[" + m.methods().indexOf(ms) + "].estimates");
        if (!Files.exists(file)) {
            return failed(ms, s, seed, rel, null, FailureDefinition.Reason.MISSING_ESTIMATE,
                    "estimate file does not exist", null);
        }
        String sha = ManifestPaths.sha256(file);
        SettingValues settings = runSettings(m, ms, s, seed, source);
        LoadedTrajectory est;
        try {
            est = ManifestPaths.renamed(engine.read(file, SettingsResolver.readOptions(settings, FileRole.ESTIMATE,
                    ReadOptions.defaults(), ManifestPaths.paths(base, source))), rel);
        } catch (InputException | UncheckedIOException e) {
            return failed(ms, s, seed, rel, sha, FailureDefinition.Reason.UNREADABLE_ESTIMATE, e.getMessage(),
                    null);
        }
        EvaluationOptions o = SettingsResolver.evaluationOptions(settings,
                DataKind.of(reference.trajectory(), est.trajectory()));
        double coverage = coverage(reference.trajectory(), est.trajectory(), o.tOffsetS());
        EvaluationReport rep;
        try {
            rep = engine.evaluate(reference, est, o);
        } catch (InputException e) {
            return failed(ms, s, seed, rel, sha, FailureDefinition.Reason.EVALUATION_REFUSED, e.getMessage(),
                    coverage);
        }
        if (rep.coverage() != null) {
            // the report's coverage: the time the associated poses cover, not the span of the file
            coverage = rep.coverage().fraction();
        }
        double[] values = new double[m.score().terms().size()];
        Map<String, Double> metrics = new LinkedHashMap<>();
        for (int j = 0; j < values.length; j++) {
            RunMetric rm = m.score().terms().get(j).metric();
            values[j] = rm.of(rep);
            metrics.put(rm.key(), SuiteAnalysis.nullable(values[j]));
        }
        double rmse = RunMetric.ATE_TRANS_RMSE_M.of(rep);
        double max = rep.ate() == null || rep.ate().transM().max() == null ? Double.NaN : rep.ate().transM().max();
        FailureDefinition.Failure f = m.failure().judge(coverage, rmse, max);
        for (double v : values) {
            if (f == null && !Double.isFinite(v)) {
                f = new FailureDefinition.Failure(FailureDefinition.Reason.DIVERGED, "a score metric is not finite");
            }
        }
        SequencePlot.Trace trace = trace(ms.name(), seed, reference.trajectory(), est.trajectory(), rep,
                rep.association() != null ? rep.association().tOffsetS() : o.tOffsetS());
        String split = s.split().key();
        if (f != null) {
            return new RunResult(new RunEntry(ms.name(), s.id(), seed, split, rel, "failed",
                    new SuiteReport.RunFailure(f.reason().name().toLowerCase(Locale.ROOT), f.detail()),
                    SuiteAnalysis.nullable(coverage), metrics, 0.0, rep), sha, trace);
        }
        return new RunResult(new RunEntry(ms.name(), s.id(), seed, split, rel, "ok", null,
                SuiteAnalysis.nullable(coverage), metrics, m.score().score(values), rep), sha, trace);
    }

    private RunResult failed(MethodSpec ms, SequenceSpec s, long seed, String rel, String sha,
            FailureDefinition.Reason reason, String detail, Double coverage) {
        Map<String, Double> metrics = new LinkedHashMap<>();
        for (NormalisedScore.Term t : m.score().terms()) {
            metrics.put(t.metric().key(), null);
        }
        return new RunResult(new RunEntry(ms.name(), s.id(), seed, s.split().key(), rel, "failed",
                new SuiteReport.RunFailure(reason.name().toLowerCase(Locale.ROOT), detail),
                coverage == null ? null : SuiteAnalysis.nullable(coverage), metrics, 0.0, null), sha, null);
    }

    /**
     * Coverage before evaluation (kept for runs the evaluation refuses): the fraction of the
     * reference's time span [r0, r1] covered by the estimate's span
     * shifted by the offset, (min(r1, e1) - max(r0, e0)) / (r1 - r0), clipped to [0, 1].
     */
    static double coverage(Trajectory ref, Trajectory est, double tOffsetS) {
        double r0 = ref.t(0);
        double r1 = ref.t(ref.size() - 1);
        double e0 = est.t(0) + tOffsetS;
        double e1 = est.t(est.size() - 1) + tOffsetS;
        if (r1 <= r0) {
            return (e0 <= r0 && r0 <= e1) ? 1.0 : 0.0;
        }
        double c = (Math.min(r1, e1) - Math.max(r0, e0)) / (r1 - r0);
        return Math.max(0.0, Math.min(1.0, c));
    }

    /**
     * The estimate moved by the report's alignment p' = s R p + t, and its position error against
     * the reference interpolated linearly at each estimate stamp inside the reference's span.
     */
    static SequencePlot.Trace trace(String method, long seed, Trajectory ref, Trajectory est, EvaluationReport rep,
            double tOffsetS) {
        double[][] r = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
        double[] t = {0, 0, 0};
        double scale = 1.0;
        if (rep.alignment() != null && rep.alignment().rotation() != null) {
            r = rep.alignment().rotation();
            double[] tt = rep.alignment().translationM();
            for (int i = 0; i < Math.min(3, tt.length); i++) {
                t[i] = tt[i];
            }
            scale = rep.alignment().scale() > 0 ? rep.alignment().scale() : 1.0;
        }
        int step = Math.max(1, est.size() / MAX_PLOT_POINTS);
        List<double[]> pts = new ArrayList<>();
        int k = 0;
        for (int i = 0; i < est.size(); i += step) {
            double px = est.x(i);
            double py = est.y(i);
            double pz = est.z(i);
            double ax = scale * (r[0][0] * px + r[0][1] * py + r[0][2] * pz) + t[0];
            double ay = scale * (r[1][0] * px + r[1][1] * py + r[1][2] * pz) + t[1];
            double az = scale * (r[2][0] * px + r[2][1] * py + r[2][2] * pz) + t[2];
            double ti = est.t(i) + tOffsetS;
            double err = Double.NaN;
            int j = ref.firstAtOrAfter(ti, 0, ref.size());
            boolean inside = j < ref.size() && (j > 0 || ref.t(0) == ti);
            if (inside) {
                int j0 = Math.max(0, j - 1);
                int j1 = Math.min(ref.size() - 1, j);
                double w = ref.t(j1) == ref.t(j0) ? 0.0 : (ti - ref.t(j0)) / (ref.t(j1) - ref.t(j0));
                double rx = ref.x(j0) + w * (ref.x(j1) - ref.x(j0));
                double ry = ref.y(j0) + w * (ref.y(j1) - ref.y(j0));
                double rz = ref.z(j0) + w * (ref.z(j1) - ref.z(j0));
                err = Math.sqrt((ax - rx) * (ax - rx) + (ay - ry) * (ay - ry) + (az - rz) * (az - rz));
            }
            pts.add(new double[] {ax, ay, az, ti - ref.t(0), err});
            k++;
        }
        double[][] c = new double[5][k];
        for (int i = 0; i < k; i++) {
            for (int j = 0; j < 5; j++) {
                c[j][i] = pts.get(i)[j];
            }
        }
        String model = rep.alignment() == null ? "none" : rep.alignment().model();
        return new SequencePlot.Trace(method, seed, c[0], c[1], c[2], c[3], c[4], model);
    }
}
