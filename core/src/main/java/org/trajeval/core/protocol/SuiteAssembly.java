package org.trajeval.core.protocol;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import org.trajeval.core.Version;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.report.SequencePlot;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.RunEntry;
import org.trajeval.core.stats.ClusteredProportion;
import org.trajeval.core.stats.WilcoxonSignedRank;
import org.trajeval.core.traj.Trajectory;

/**
 * The analysis of a suite on one machine (the driver), once every run is scored: the runs'
 * results (in the plan's task order, wherever they were scored) become the report (budget check,
 * per-method summaries, paired comparisons with Holm, rankings, domain gap, factor sweeps, slices,
 * hygiene warnings, input digests) and the HTML page's plots. It depends only on the results'
 * values, never on where or in which order they were computed.
 */
public final class SuiteAssembly {
    private SuiteAssembly() {
    }

    /** @return the keys the suite compares: the score's metrics, then the score itself */
    static List<String> comparedKeys(SuiteManifest m) {
        List<String> compared = new ArrayList<>(m.score().terms().stream().map(t -> t.metric().key()).toList());
        compared.add(SuiteAnalysis.SCORE);
        return compared;
    }

    /**
     * @param plan the suite's plan
     * @param results one result per task of the plan, in task order
     * @param settings the statistics' settings
     * @return the report and the plots
     * @throws IllegalArgumentException when the results do not match the plan's tasks
     * @throws org.trajeval.core.InputException on a bad resources table
     */
    public static SuiteRunner.Result assemble(SuitePlan plan, List<RunResult> results, SuiteRunner.Settings settings) {
        if (results.size() != plan.tasks().size()) {
            throw new IllegalArgumentException(results.size() + " results for " + plan.tasks().size() + " tasks");
        }
        for (int i = 0; i < results.size(); i++) {
            RunTask t = plan.tasks().get(i);
            RunEntry e = results.get(i).entry();
            if (!(t.method().equals(e.method()) && t.sequence().equals(e.sequence()) && t.seed() == e.seed())) {
                throw new IllegalArgumentException("result " + i + " (" + e.method() + ", " + e.sequence() + ", "
                        + e.seed() + ") is not the result of task " + t);
            }
        }
        SuiteManifest m = plan.manifest();
        SeedSetCheck seeds = plan.seeds();
        List<SplitLeakage> leaks = plan.leaks();
        List<SequenceSpec> evaluated = plan.evaluated();
        Map<String, LoadedTrajectory> references = plan.references();
        Map<String, String> digests = new TreeMap<>(plan.digests());
        Map<String, String> roles = new TreeMap<>(plan.roles());
        List<RunEntry> scored = new ArrayList<>();
        for (RunResult o : results) {
            scored.add(o.entry());
            if (o.sha256() != null) {
                digests.put(o.entry().estimate(), o.sha256());
                roles.put(o.entry().estimate(), "estimate");
            }
        }
        String source = plan.manifestFile().toString();
        Path base = plan.manifestFile().toAbsolutePath().normalize().getParent();
        ResourcesTable table = ResourcesTable.empty();
        if (m.resources() != null) {
            Path file = ManifestPaths.inside(base, m.resources(), source, "resources");
            table = ResourcesTable.read(file, new java.util.HashSet<>(m.methods().stream().map(MethodSpec::name)
                    .toList()), new java.util.HashSet<>(m.sequences().stream().map(SequenceSpec::id).toList()));
            digests.put(m.resources(), ManifestPaths.sha256(file));
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
        List<String> compared = comparedKeys(m);
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
                protocol(m, plan.manifestFile(), seeds, settings, references.values().stream().allMatch(r ->
                        r.trajectory() instanceof org.trajeval.core.traj.PlanarTrajectory) ? DataKind.PLANAR
                        : DataKind.SPATIAL), new SuiteReport.Hygiene(leaks.stream().map(l ->
                        new SuiteReport.Leak(l.unit().name().toLowerCase(Locale.ROOT), l.id(), leakMembers(l)))
                        .toList(), !leaks.isEmpty(), warnings),
                inputs, summaries, ranking.comparisons(), ranking.rankings(),
                DomainGap.compute(evaluated, runsByMethod, compared, stats),
                FactorSweeps.compute(evaluated, runsByMethod, compared, settings.level(), m.failure().breakdownRate()),
                budgets.report(), Slices.compute(evaluated, runsByMethod, keys, settings.level()), runs);

        return new SuiteRunner.Result(report, plots(plan, results));
    }

    /** Per evaluated sequence, its reference (at most {@value RunScorer#MAX_PLOT_POINTS} points) and runs' traces. */
    private static List<SequencePlot> plots(SuitePlan plan, List<RunResult> results) {
        List<SequencePlot> plots = new ArrayList<>();
        for (SequenceSpec s : plan.evaluated()) {
            Trajectory ref = plan.references().get(s.id()).trajectory();
            List<SequencePlot.Trace> traces = new ArrayList<>();
            for (RunResult o : results) {
                if (o.trace() != null && o.entry().sequence().equals(s.id())) {
                    traces.add(o.trace());
                }
            }
            int step = Math.max(1, ref.size() / RunScorer.MAX_PLOT_POINTS);
            int k = (ref.size() + step - 1) / step;
            double[] rx = new double[k];
            double[] ry = new double[k];
            double[] rz = new double[k];
            for (int i = 0, j = 0; i < ref.size(); i += step, j++) {
                rx[j] = ref.x(i);
                ry[j] = ref.y(i);
                rz[j] = ref.z(i);
            }
            String unit = plan.references().get(s.id()).indexTimestamps() ? "frame" : "s";
            plots.add(new SequencePlot(s.id(), unit, rx, ry, rz, traces));
        }
        return plots;
    }

    private static Map<String, List<String>> leakMembers(SplitLeakage l) {
        Map<String, List<String>> out = new LinkedHashMap<>();
        l.members().forEach((k, v) -> out.put(k.key(), v));
        return out;
    }

    private static List<RunEntry> runsOf(List<RunEntry> runs, String method) {
        return runs.stream().filter(r -> r.method().equals(method)).toList();
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
}
