package org.trajeval.core.protocol;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.LoadedTrajectory;

/**
 * A suite planned on one machine (the driver) before any run is scored: split and seed hygiene
 * checked, the references of the evaluated sequences read and hashed, and the run tasks listed,
 * for every method, evaluated sequence (manifest order) and common seed (ascending), in that
 * nesting. The tasks are scored anywhere by the {@link RunScorer} of the same manifest; the
 * {@link SuiteAssembly} turns their results into the report.
 *
 * @param manifest the parsed manifest
 * @param manifestFile where it was read from
 * @param leaks the split leakage found (empty, or allowed by the settings)
 * @param seeds the seed-set check (its common seeds are the ones run)
 * @param evaluated the sequences of the evaluated splits, in manifest order
 * @param references per evaluated sequence id, its reference
 * @param digests per input path as the manifest wrote it (manifest and references), SHA-256
 * @param roles per input path, its role (manifest, reference)
 * @param tasks the runs to score, {@link RunTask#index()} = position
 */
public record SuitePlan(SuiteManifest manifest, Path manifestFile, List<SplitLeakage> leaks, SeedSetCheck seeds,
        List<SequenceSpec> evaluated, Map<String, LoadedTrajectory> references, Map<String, String> digests,
        Map<String, String> roles, List<RunTask> tasks) {

    /** Copies the collections (maps keep their order). */
    public SuitePlan {
        Objects.requireNonNull(manifest, "manifest");
        Objects.requireNonNull(manifestFile, "manifestFile");
        Objects.requireNonNull(seeds, "seeds");
        leaks = List.copyOf(leaks);
        evaluated = List.copyOf(evaluated);
        references = Collections.unmodifiableMap(new LinkedHashMap<>(references));
        digests = Collections.unmodifiableMap(new TreeMap<>(digests));
        roles = Collections.unmodifiableMap(new TreeMap<>(roles));
        tasks = List.copyOf(tasks);
    }

    /**
     * Plans the suite of a parsed manifest.
     *
     * @param m the manifest
     * @param manifestFile where it was read from (the base of its paths)
     * @param settings the run's settings (leakage allowed or not, the {@code --detect} targets)
     * @param scorer the scorer of the same manifest (reads the references)
     * @throws SplitLeakageException on leakage unless allowed
     * @throws InputException on no common seed, a missing or bad reference, a path leaving the
     *     manifest's folder, or a {@code --detect} metric the suite does not compare
     */
    public static SuitePlan of(SuiteManifest m, Path manifestFile, SuiteRunner.Settings settings, RunScorer scorer) {
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
        digests.put(manifestFile.getFileName().toString(), ManifestPaths.sha256(manifestFile));
        roles.put(manifestFile.getFileName().toString(), "manifest");

        Map<String, LoadedTrajectory> references = new LinkedHashMap<>();
        for (int i = 0; i < m.sequences().size(); i++) {
            SequenceSpec s = m.sequences().get(i);
            if (!evaluated.contains(s)) {
                continue;
            }
            Path file = scorer.referenceFile(i);
            references.put(s.id(), scorer.reference(s.id()));
            digests.put(s.reference(), ManifestPaths.sha256(file));
            roles.put(s.reference(), "reference");
        }

        List<RunTask> tasks = new ArrayList<>();
        for (MethodSpec ms : m.methods()) {
            for (SequenceSpec s : evaluated) {
                for (long seed : seeds.common()) {
                    String rel = ms.estimateFor(s.id(), seed);
                    ManifestPaths.inside(base, rel, source, "methods[" + m.methods().indexOf(ms) + "].estimates");
                    tasks.add(new RunTask(tasks.size(), ms.name(), s.id(), seed, rel));
                }
            }
        }
        List<String> compared = SuiteAssembly.comparedKeys(m);
        for (String k : settings.targets().keySet()) {
            if (!compared.contains(k)) {
                throw new InputException(null, 0, "--detect", InputProblem.INVALID_OPTION, "--detect: the suite "
                        + "compares no metric '" + k + "'; expected one of " + compared, k);
            }
        }
        return new SuitePlan(m, manifestFile, leaks, seeds, evaluated, references, digests, roles, tasks);
    }

    /** @return the manifest's SHA-256, as hashed when the plan was made */
    public String manifestSha256() {
        return digests.get(manifestFile.getFileName().toString());
    }
}
