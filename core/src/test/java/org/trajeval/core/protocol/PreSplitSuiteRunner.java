package org.trajeval.core.protocol;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.Version;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.FileRole;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.SettingText;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.SequencePlot;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.RunEntry;
import org.trajeval.core.stats.ClusteredProportion;
import org.trajeval.core.stats.WilcoxonSignedRank;
import org.trajeval.core.traj.Trajectory;

/**
 * The suite runner as it was before it was split into planning, per-run scoring and analysis
 * (SuiteRunner.java at commit 4e6f81a, unchanged but for its name and the types it now shares with
 * SuiteRunner): the oracle of {@link SuiteSplitTest}, which checks that the split path writes the same
 * report. Delete it with that test once the split has settled.
 *
 * <p>Runs a suite: checks split and seed hygiene, scores every (method, sequence, seed) run of the
 * evaluated splits and the common seeds with the engine (on the injected executor), counts
 * failures, and computes the statistics of {@link SuiteAnalysis}. The result does not depend on
 * the number of threads.
 */
final class PreSplitSuiteRunner {
    /** Most points drawn per trace in the HTML plots. */
    static final int MAX_PLOT_POINTS = 1500;

    private final RunEngine engine;
    private final ExecutorService executor;
    private final SuiteRunner.Progress progress;

    /**
     * @param engine reader and evaluator
     * @param executor runs the runs (not shut down here)
     * @param progress progress listener
     */
    PreSplitSuiteRunner(RunEngine engine, ExecutorService executor, SuiteRunner.Progress progress) {
        this.engine = Objects.requireNonNull(engine, "engine");
        this.executor = Objects.requireNonNull(executor, "executor");
        this.progress = Objects.requireNonNull(progress, "progress");
    }

    /**
     * Runs the suite of the manifest at {@code manifestFile}.
     *
     * @throws SplitLeakageException on leakage unless allowed
     * @throws InputException on a manifest problem, a missing or bad reference, or no common seed
     */
    SuiteRunner.Result run(Path manifestFile, SuiteRunner.Settings settings) {
        SuiteManifest m = new ManifestParser().read(manifestFile);
        return run(m, manifestFile, settings);
    }

    /** Runs an already parsed manifest whose paths are relative to {@code manifestFile}'s folder. */
    SuiteRunner.Result run(SuiteManifest m, Path manifestFile, SuiteRunner.Settings settings) {
        String source = manifestFile.toString();
        Path base = manifestFile.toAbsolutePath().normalize().getParent();
        List<SplitLeakage> leaks = SplitLeakage.find(SplitLeakage.assignments(m));
        if (!leaks.isEmpty() && !settings.allowLeakage()) {
            throw new SplitLeakageException(source, leaks);
        }
        SeedSetCheck seeds = SeedSetCheck.of(m);
        if (seeds.common().isEmpty()) {
            throw new InputException(source, 0, "methods", InputProblem.INVALID_CONFIGURATION,
                    "no seed is common to all methods: " + seeds.deviations().stream()
                            .map(SeedSetCheck.Deviation::describe).toList(), null);
        }
        List<SequenceSpec> evaluated = m.sequences().stream().filter(s -> m.evaluatedSplits().contains(s.split()))
                .toList();
        Map<String, String> digests = new TreeMap<>();
        Map<String, String> roles = new TreeMap<>();
        digests.put(manifestFile.getFileName().toString(), sha256(manifestFile));
        roles.put(manifestFile.getFileName().toString(), "manifest");

        Map<String, LoadedTrajectory> references = new LinkedHashMap<>();
        for (int i = 0; i < m.sequences().size(); i++) {
            SequenceSpec s = m.sequences().get(i);
            if (!evaluated.contains(s)) {
                continue;
            }
            Path file = inside(base, s.reference(), source, "sequences[" + i + "].reference");
            if (!Files.isRegularFile(file)) {
                throw new InputException(source, 0, "sequences[" + i + "].reference", InputProblem.UNREADABLE,
                        "'sequences[" + i + "].reference': reference file does not exist", s.reference());
            }
            SettingValues settingsOfSequence = m.metrics().with(s.settings(), source);
            references.put(s.id(), renamed(engine.read(file, SettingsResolver.readOptions(settingsOfSequence,
                    FileRole.REFERENCE, ReadOptions.defaults(), paths(base, source))), s.reference()));
            digests.put(s.reference(), sha256(file));
            roles.put(s.reference(), "reference");
        }

        List<Callable<Outcome>> tasks = new ArrayList<>();
        for (MethodSpec ms : m.methods()) {
            for (SequenceSpec s : evaluated) {
                for (long seed : seeds.common()) {
                    String rel = ms.estimateFor(s.id(), seed);
                    Path file = inside(base, rel, source, "methods[" + m.methods().indexOf(ms) + "].estimates");
                    tasks.add(() -> runOne(m, manifestFile, ms, s, seed, rel, file, references.get(s.id()), true));
                }
            }
        }
        int total = tasks.size();
        AtomicInteger done = new AtomicInteger();
        List<Future<Outcome>> futures = new ArrayList<>();
        for (Callable<Outcome> t : tasks) {
            futures.add(executor.submit(() -> {
                Outcome o = t.call();
                progress.runFinished(done.incrementAndGet(), total);
                return o;
            }));
        }
        List<Outcome> outcomes = new ArrayList<>();
        for (Future<Outcome> f : futures) {
            try {
                outcomes.add(f.get());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IllegalStateException("suite interrupted", e);
            } catch (ExecutionException e) {
                if (e.getCause() instanceof RuntimeException re) {
                    throw re;
                }
                throw new IllegalStateException(e.getCause());
            }
        }
        List<RunEntry> scored = new ArrayList<>();
        for (Outcome o : outcomes) {
            scored.add(o.entry());
            if (o.sha256() != null) {
                digests.put(o.entry().estimate(), o.sha256());
                roles.put(o.entry().estimate(), "estimate");
            }
        }
        ResourcesTable table = ResourcesTable.empty();
        if (m.resources() != null) {
            Path file = inside(base, m.resources(), source, "resources");
            table = ResourcesTable.read(file, new java.util.HashSet<>(m.methods().stream().map(MethodSpec::name)
                    .toList()), new java.util.HashSet<>(m.sequences().stream().map(SequenceSpec::id).toList()));
            digests.put(m.resources(), sha256(file));
            roles.put(m.resources(), "resources");
        }
        Map<String, Double> durations = new LinkedHashMap<>();
        references.forEach((id, r) -> durations.put(id, r.indexTimestamps() ? null
                : r.trajectory().t(r.trajectory().size() - 1) - r.trajectory().t(0)));
        BudgetCheck.Applied budgets = BudgetCheck.apply(m, table, scored, durations);
        List<RunEntry> runs = budgets.runs();
        List<SuiteReport.InputDigest> inputs = new ArrayList<>();
        digests.forEach((p, h) -> inputs.add(new SuiteReport.InputDigest(roles.get(p), p, h)));

        List<String> seqIds = evaluated.stream().map(SequenceSpec::id).toList();
        List<String> keys = m.score().terms().stream().map(t -> t.metric().key()).toList();
        List<SuiteReport.MethodSummary> summaries = new ArrayList<>();
        for (MethodSpec ms : m.methods()) {
            summaries.add(SuiteAnalysis.summarise(ms.name(), seqIds, runsOf(runs, ms.name()), keys,
                    settings.level()));
        }
        SuiteAnalysis.Settings stats = new SuiteAnalysis.Settings(settings.seed(), settings.level(),
                settings.resamples(), settings.power(), settings.targets());
        List<SuiteReport.Comparison> comparisons = new ArrayList<>();
        List<String> compared = new ArrayList<>(keys);
        compared.add(SuiteAnalysis.SCORE);
        for (String k : settings.targets().keySet()) {
            if (!compared.contains(k)) {
                throw new IllegalArgumentException("--detect: the suite compares no metric '" + k
                        + "'; expected one of " + compared);
            }
        }
        int stream = 0;
        for (int a = 0; a < m.methods().size(); a++) {
            for (int b = a + 1; b < m.methods().size(); b++) {
                String na = m.methods().get(a).name();
                String nb = m.methods().get(b).name();
                for (String key : compared) {
                    comparisons.add(SuiteAnalysis.compare(na, runsOf(runs, na), nb, runsOf(runs, nb), seqIds, key,
                            stats, stream++));
                }
            }
        }
        List<String> methodNames = m.methods().stream().map(MethodSpec::name).toList();
        Map<String, List<RunEntry>> runsByMethod = new LinkedHashMap<>();
        methodNames.forEach(name -> runsByMethod.put(name, runsOf(runs, name)));
        MethodRanking.Result ranking = MethodRanking.of(methodNames, runsByMethod, seqIds, compared, comparisons,
                settings.level());

        List<String> warnings = new ArrayList<>();
        for (SplitLeakage l : leaks) {
            warnings.add("LEAKAGE (allowed by --allow-leakage): " + l.describe());
        }
        for (SeedSetCheck.Deviation d : seeds.deviations()) {
            warnings.add("SEEDS: " + d.describe() + "; statistics use only the common seeds " + seeds.common());
        }
        String simOnly = DomainGap.simOnlyWarning(evaluated);
        if (simOnly != null) {
            warnings.add(simOnly);
        }
        warnings.addAll(FactorSweeps.oneFactorAtATimeWarnings(evaluated));
        warnings.addAll(budgets.warnings());
        SuiteReport report = new SuiteReport(SuiteReport.SCHEMA, SuiteReport.SCHEMA_VERSION, Version.TOOL,
                protocol(m, manifestFile, seeds, settings, references.values().stream().allMatch(r ->
                        r.trajectory() instanceof org.trajeval.core.traj.PlanarTrajectory) ? DataKind.PLANAR
                        : DataKind.SPATIAL), new SuiteReport.Hygiene(leaks.stream().map(l ->
                        new SuiteReport.Leak(l.unit().name().toLowerCase(Locale.ROOT), l.id(), leakMembers(l)))
                        .toList(), !leaks.isEmpty(), warnings),
                inputs, summaries, ranking.comparisons(), ranking.rankings(),
                DomainGap.compute(evaluated, runsByMethod, compared, stats),
                FactorSweeps.compute(evaluated, runsByMethod, compared, settings.level(), m.failure().breakdownRate()),
                budgets.report(), Slices.compute(evaluated, runsByMethod, keys, settings.level()), runs);

        List<SequencePlot> plots = new ArrayList<>();
        for (SequenceSpec s : evaluated) {
            Trajectory ref = references.get(s.id()).trajectory();
            List<SequencePlot.Trace> traces = new ArrayList<>();
            for (Outcome o : outcomes) {
                if (o.trace() != null && o.entry().sequence().equals(s.id())) {
                    traces.add(o.trace());
                }
            }
            int step = Math.max(1, ref.size() / MAX_PLOT_POINTS);
            int k = (ref.size() + step - 1) / step;
            double[] rx = new double[k];
            double[] ry = new double[k];
            double[] rz = new double[k];
            for (int i = 0, j = 0; i < ref.size(); i += step, j++) {
                rx[j] = ref.x(i);
                ry[j] = ref.y(i);
                rz[j] = ref.z(i);
            }
            plots.add(new SequencePlot(s.id(), references.get(s.id()).indexTimestamps() ? "frame" : "s", rx, ry, rz,
                    traces));
        }
        return new SuiteRunner.Result(report, plots);
    }

    private static Map<String, List<String>> leakMembers(SplitLeakage l) {
        Map<String, List<String>> out = new LinkedHashMap<>();
        l.members().forEach((k, v) -> out.put(k.key(), v));
        return out;
    }

    private static List<RunEntry> runsOf(List<RunEntry> runs, String method) {
        return runs.stream().filter(r -> r.method().equals(method)).toList();
    }

    /** The outcome of one run: its report entry, the estimate's digest and its plot trace. */
    private record Outcome(RunEntry entry, String sha256, SequencePlot.Trace trace) {
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

    /** Path settings of a manifest: relative to its folder, which they may not leave. */
    private static PathResolver paths(Path base, String source) {
        return (text, where) -> inside(base, text.replace('\\', '/'), source, where);
    }

    private Outcome runOne(SuiteManifest m, Path manifestFile, MethodSpec ms, SequenceSpec s, long seed, String rel,
            Path file, LoadedTrajectory reference, boolean plot) {
        if (!Files.exists(file)) {
            return failed(m, ms, s, seed, rel, null, FailureDefinition.Reason.MISSING_ESTIMATE,
                    "estimate file does not exist", null);
        }
        String sha = sha256(file);
        String source = manifestFile.toString();
        SettingValues settings = runSettings(m, ms, s, seed, source);
        LoadedTrajectory est;
        try {
            est = renamed(engine.read(file, SettingsResolver.readOptions(settings, FileRole.ESTIMATE,
                    ReadOptions.defaults(), paths(manifestFile.toAbsolutePath().normalize().getParent(), source))),
                    rel);
        } catch (InputException | UncheckedIOException e) {
            return failed(m, ms, s, seed, rel, sha, FailureDefinition.Reason.UNREADABLE_ESTIMATE, e.getMessage(),
                    null);
        }
        EvaluationOptions o = SettingsResolver.evaluationOptions(settings,
                DataKind.of(reference.trajectory(), est.trajectory()));
        double coverage = coverage(reference.trajectory(), est.trajectory(), o.tOffsetS());
        EvaluationReport rep;
        try {
            rep = engine.evaluate(reference, est, o);
        } catch (InputException e) {
            return failed(m, ms, s, seed, rel, sha, FailureDefinition.Reason.EVALUATION_REFUSED, e.getMessage(),
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
        SequencePlot.Trace trace = plot ? trace(ms.name(), seed, reference.trajectory(), est.trajectory(), rep,
                rep.association() != null ? rep.association().tOffsetS() : o.tOffsetS()) : null;
        String split = s.split().key();
        if (f != null) {
            return new Outcome(new RunEntry(ms.name(), s.id(), seed, split, rel, "failed",
                    new SuiteReport.RunFailure(f.reason().name().toLowerCase(Locale.ROOT), f.detail()),
                    SuiteAnalysis.nullable(coverage), metrics, 0.0, rep), sha, trace);
        }
        return new Outcome(new RunEntry(ms.name(), s.id(), seed, split, rel, "ok", null,
                SuiteAnalysis.nullable(coverage), metrics, m.score().score(values), rep), sha, trace);
    }

    private static Outcome failed(SuiteManifest m, MethodSpec ms, SequenceSpec s, long seed, String rel, String sha,
            FailureDefinition.Reason reason, String detail, Double coverage) {
        Map<String, Double> metrics = new LinkedHashMap<>();
        for (NormalisedScore.Term t : m.score().terms()) {
            metrics.put(t.metric().key(), null);
        }
        return new Outcome(new RunEntry(ms.name(), s.id(), seed, s.split().key(), rel, "failed",
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

    /** The protocol as run; metric settings resolved for the references' data kind (an estimate may add its own). */
    private static SuiteReport.Protocol protocol(SuiteManifest m, Path manifestFile, SeedSetCheck seeds,
            SuiteRunner.Settings settings, DataKind kind) {
        EvaluationOptions o = SettingsResolver.evaluationOptions(m.metrics(), kind);
        SuiteReport.MetricSettings ms = new SuiteReport.MetricSettings(lower(o.convention()), lower(o.association()),
                o.maxDiffS(), lower(o.overlap()), lower(o.alignment()), o.rpeDelta(), o.rpeUnit().symbol(),
                lower(o.pairSelection()), o.drift() == null ? null : o.drift().segmentLengthsM(),
                o.drift() == null ? null : o.drift().stepFrames());
        List<SuiteReport.SequenceEntry> seqs = m.sequences().stream().map(s -> new SuiteReport.SequenceEntry(s.id(),
                s.session(), s.split().key(), s.reference(), s.tags(), s.about().domain(), s.about().simulator(),
                s.about().scenario(), s.about().factors(), s.about().environment(), s.about().modality(),
                s.about().groundTruth())).toList();
        SuiteReport.Seeds sd = new SuiteReport.Seeds(seeds.declared(), seeds.common(), seeds.deviations().stream()
                .map(d -> new SuiteReport.SeedDeviation(d.method(), d.missing(), d.extra())).toList());
        Budget b = m.budget();
        FailureDefinition f = m.failure();
        return new SuiteReport.Protocol(m.name(), manifestFile.getFileName().toString(),
                m.evaluatedSplits().stream().map(Split::key).toList(), seqs, ms, sd,
                new SuiteReport.BudgetEntry(b.device(), b.cores(), b.realTimeFactor(), b.memoryCapMib()),
                new SuiteReport.FailureSettings(List.of("missing_estimate", "unreadable_estimate",
                        "evaluation_refused"), f.minCoverage(), f.maxAteTransRmseM(), f.divergenceTransM()),
                m.score().terms().stream().map(t -> new SuiteReport.ScoreTerm(t.metric().key(), t.cap(), t.weight()))
                        .toList(),
                new SuiteReport.Analysis(settings.seed(), settings.level(), settings.resamples(),
                        WilcoxonSignedRank.EXACT_MAX_N, settings.power(), new java.util.TreeMap<>(settings.targets()),
                        "holm", ClusteredProportion.METHOD));
    }

    private static String lower(Enum<?> e) {
        return e.name().toLowerCase(Locale.ROOT);
    }

    private static LoadedTrajectory renamed(LoadedTrajectory t, String source) {
        return new LoadedTrajectory(source, t.format(), t.formatReason(), t.trajectory(), t.sha256(),
                t.indexTimestamps());
    }

    /** Resolves a manifest-relative path and refuses one that leaves the folder, also through symbolic links. */
    private static Path inside(Path base, String rel, String source, String key) {
        Path p = base.resolve(rel).normalize();
        boolean escapes = !p.startsWith(base);
        if (!escapes && Files.exists(p)) {
            try {
                escapes = !p.toRealPath().startsWith(base.toRealPath());
            } catch (IOException e) {
                throw new UncheckedIOException("could not resolve " + rel, e);
            }
        }
        if (escapes) {
            throw new InputException(source, 0, key, InputProblem.PATH_ESCAPES,
                    "'" + key + "': path leaves the manifest's folder", rel);
        }
        return p;
    }

    /** @return SHA-256 of the file's bytes, lower-case hex */
    static String sha256(Path file) {
        try (InputStream in = Files.newInputStream(file)) {
            MessageDigest md = MessageDigest.getInstance("SHA-256");
            byte[] buf = new byte[1 << 16];
            int n;
            while ((n = in.read(buf)) > 0) {
                md.update(buf, 0, n);
            }
            return HexFormat.of().formatHex(md.digest());
        } catch (IOException e) {
            throw new UncheckedIOException("could not read " + file, e);
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("SHA-256 is not available", e);
        }
    }
}
