package org.trajeval.core.protocol;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicInteger;
import org.trajeval.core.InputException;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.report.SequencePlot;
import org.trajeval.core.report.SuiteReport;

/**
 * Runs a suite on one machine: {@link SuitePlan} (split and seed hygiene, references, the run
 * tasks), then every task scored by the {@link RunScorer} on the injected executor, then
 * {@link SuiteAssembly} (failures counted, the statistics of {@link SuiteAnalysis}). The result does
 * not depend on the number of threads; {@code trajeval-spark suite} runs the same three steps with
 * the scoring on a cluster.
 */
public final class SuiteRunner {
    private final RunEngine engine;
    private final ExecutorService executor;
    private final Progress progress;

    /** Told after each finished run; called from worker threads. */
    @FunctionalInterface
    public interface Progress {
        /**
         * @param done runs finished so far
         * @param total runs in the suite
         */
        void runFinished(int done, int total);

        /** @return a listener that does nothing */
        static Progress none() {
            return (d, t) -> { };
        }
    }

    /**
     * @param seed seed of the statistics (bootstrap)
     * @param allowLeakage run despite split leakage (flagged in the report)
     * @param level confidence level of every interval
     * @param resamples bootstrap resamples
     * @param power power of the planning figures
     * @param targets per metric key, a mean difference whose needed number of sequences is reported
     */
    public record Settings(long seed, boolean allowLeakage, double level, int resamples, double power,
            Map<String, Double> targets) {
        /** Copies the targets. */
        public Settings {
            targets = Map.copyOf(targets);
        }

        /** Planning at {@link org.trajeval.core.stats.PowerPlanning#DEFAULT_POWER}, no target difference. */
        public Settings(long seed, boolean allowLeakage, double level, int resamples) {
            this(seed, allowLeakage, level, resamples, org.trajeval.core.stats.PowerPlanning.DEFAULT_POWER, Map.of());
        }

        /** @return seed {@code seed}, leakage refused, 95 %, 4000 resamples */
        public static Settings defaults(long seed) {
            return new Settings(seed, false, 0.95, org.trajeval.core.stats.BootstrapInterval.DEFAULT_RESAMPLES);
        }

        /**
         * Checks the settings as a command line gives them, naming the options of {@code trajeval suite}.
         *
         * @return these settings
         * @throws InputException on a level outside (0, 1), fewer than 100 or more than 10^6 resamples, a power
         *     outside (0.5, 1), or a {@code --detect} difference that is zero or not finite
         */
        public Settings checked() {
            if (!(level > 0.0 && level < 1.0)) {
                throw option("--confidence", "--confidence must be a level between 0 and 1 (exclusive)", level);
            }
            if (resamples < 100 || resamples > 1_000_000) {
                throw option("--resamples", "--resamples must be 100 to 1000000", resamples);
            }
            if (!(power > 0.5 && power < 1.0)) {
                throw option("--power", "--power must be a probability between 0.5 and 1 (exclusive)", power);
            }
            for (Map.Entry<String, Double> e : targets.entrySet()) {
                if (e.getValue() == null || e.getValue() == 0.0 || !Double.isFinite(e.getValue())) {
                    throw option("--detect", "--detect " + e.getKey() + " must be a finite non-zero difference",
                            e.getValue());
                }
            }
            return this;
        }

        private static InputException option(String option, String detail, Object found) {
            return new InputException(null, 0, option, org.trajeval.core.InputProblem.INVALID_OPTION, detail,
                    String.valueOf(found));
        }

        /** @return a copy allowing leakage or not */
        public Settings withAllowLeakage(boolean allow) {
            return new Settings(seed, allow, level, resamples, power, targets);
        }
    }

    /**
     * @param report the suite report (what report.json holds)
     * @param plots per evaluated sequence, what the HTML page draws
     */
    public record Result(SuiteReport report, List<SequencePlot> plots) {
    }

    /**
     * @param engine reader and evaluator
     * @param executor runs the runs (not shut down here)
     * @param progress progress listener
     */
    public SuiteRunner(RunEngine engine, ExecutorService executor, Progress progress) {
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
    public Result run(Path manifestFile, Settings settings) {
        SuiteManifest m = new ManifestParser().read(manifestFile);
        return run(m, manifestFile, settings);
    }

    /** Runs an already parsed manifest whose paths are relative to {@code manifestFile}'s folder. */
    public Result run(SuiteManifest m, Path manifestFile, Settings settings) {
        RunScorer scorer = new RunScorer(engine, m, manifestFile);
        SuitePlan plan = SuitePlan.of(m, manifestFile, settings, scorer);
        int total = plan.tasks().size();
        AtomicInteger done = new AtomicInteger();
        List<Future<RunResult>> futures = new ArrayList<>();
        for (RunTask t : plan.tasks()) {
            LoadedTrajectory reference = plan.references().get(t.sequence());
            futures.add(executor.submit(() -> {
                RunResult o = scorer.score(t, reference);
                progress.runFinished(done.incrementAndGet(), total);
                return o;
            }));
        }
        List<RunResult> results = new ArrayList<>();
        for (Future<RunResult> f : futures) {
            try {
                results.add(f.get());
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
        return SuiteAssembly.assemble(plan, results, settings);
    }
}
