package org.trajeval.core.report;

import com.fasterxml.jackson.annotation.JsonInclude;
import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.util.List;
import java.util.Map;

/**
 * The report of one benchmark suite ({@code trajeval suite}, file {@code report.json}): the
 * protocol tuple, split and seed hygiene, input digests, per-method summaries, paired comparisons
 * and every run. Versioned by {@link #SCHEMA} / {@link #SCHEMA_VERSION}; the JSON Schema is
 * {@code docs/suite-report.schema.json}. Deterministic: no timestamps, no absolute paths, so the
 * same manifest, inputs and seed give byte-identical JSON. Values that do not exist (a standard
 * deviation of one value, an interval of too few sequences) are {@code null}, never NaN.
 *
 * @param schema always {@link #SCHEMA}
 * @param schemaVersion always {@link #SCHEMA_VERSION}
 * @param version trajeval version that wrote the report
 * @param protocol the protocol tuple (dataset, splits, metrics, seeds, budget, failure, score, analysis)
 * @param hygiene split leakage and seed-set findings
 * @param inputs SHA-256 of every input file, sorted by path
 * @param methods one summary per method, in manifest order
 * @param comparisons paired comparisons of every pair of methods and every compared metric
 * @param rankings with three or more methods, per compared metric: Friedman test, average ranks and the
 *     rank diagram's groups (empty with fewer methods)
 * @param domainGap simulation beside reality (null unless the suite has both sim and real sequences)
 * @param factorSweeps one stress sweep per declared factor (empty without factors)
 * @param budgets the runs' measured resources against the budget
 * @param slices the methods' tables per domain, environment, modality and ground-truth type
 * @param runs every (method, sequence, seed) run, sorted by method (manifest order), sequence, seed
 */
@JsonPropertyOrder({"schema", "schema_version", "version", "protocol", "hygiene", "inputs", "methods", "comparisons",
    "rankings", "domain_gap", "factor_sweeps", "budgets", "slices", "runs"})
@JsonInclude(JsonInclude.Include.ALWAYS)
public record SuiteReport(
        @JsonProperty("schema") String schema,
        @JsonProperty("schema_version") int schemaVersion,
        @JsonProperty("version") String version,
        @JsonProperty("protocol") Protocol protocol,
        @JsonProperty("hygiene") Hygiene hygiene,
        @JsonProperty("inputs") List<InputDigest> inputs,
        @JsonProperty("methods") List<MethodSummary> methods,
        @JsonProperty("comparisons") List<Comparison> comparisons,
        @JsonProperty("rankings") List<Ranking> rankings,
        @JsonProperty("domain_gap") DomainGapReport domainGap,
        @JsonProperty("factor_sweeps") List<FactorSweep> factorSweeps,
        @JsonProperty("budgets") BudgetReport budgets,
        @JsonProperty("slices") List<SliceReport> slices,
        @JsonProperty("runs") List<RunEntry> runs) {

    /** A report without the simulation, sweep, budget and slice sections. */
    public SuiteReport(String schema, int schemaVersion, String version, Protocol protocol, Hygiene hygiene,
            List<InputDigest> inputs, List<MethodSummary> methods, List<Comparison> comparisons,
            List<Ranking> rankings, List<RunEntry> runs) {
        this(schema, schemaVersion, version, protocol, hygiene, inputs, methods, comparisons, rankings, null,
                List.of(), null, List.of(), runs);
    }

    /** Name of the report schema. */
    public static final String SCHEMA = "trajeval.suite-report";
    /** Version of the report schema; bumped on any incompatible change. */
    public static final int SCHEMA_VERSION = 1;

    /**
     * The protocol tuple result = (dataset, split, metric, seed, budget) of the lesson.
     *
     * @param dataset benchmark name from the manifest
     * @param manifest the manifest's file name
     * @param evaluatedSplits splits whose sequences are scored and compared
     * @param sequences every sequence with its session and split
     * @param metrics evaluation settings of every run
     * @param seeds declared and common seed sets
     * @param budget the compute budget
     * @param failure the failure definition
     * @param score the normalised score's terms
     * @param analysis settings of the statistics
     */
    @JsonPropertyOrder({"dataset", "manifest", "evaluated_splits", "sequences", "metrics", "seeds", "budget",
        "failure", "score", "analysis"})
    public record Protocol(@JsonProperty("dataset") String dataset, @JsonProperty("manifest") String manifest,
            @JsonProperty("evaluated_splits") List<String> evaluatedSplits,
            @JsonProperty("sequences") List<SequenceEntry> sequences,
            @JsonProperty("metrics") MetricSettings metrics, @JsonProperty("seeds") Seeds seeds,
            @JsonProperty("budget") BudgetEntry budget, @JsonProperty("failure") FailureSettings failure,
            @JsonProperty("score") List<ScoreTerm> score, @JsonProperty("analysis") Analysis analysis) {
    }

    /**
     * @param id sequence id
     * @param session session id
     * @param split train, val or test
     * @param reference reference file, relative to the manifest
     * @param tags environment tags
     * @param domain sim or real, or null
     * @param simulator the simulator, or null
     * @param scenario the scenario id, or null
     * @param factors controlled factor levels by name (may be empty)
     * @param environment environment type, or null
     * @param modality sensing modality (words joined by '+'), or null
     * @param groundTruth ground-truth source, or null
     */
    @JsonPropertyOrder({"id", "session", "split", "reference", "tags", "domain", "simulator", "scenario", "factors",
        "environment", "modality", "ground_truth"})
    public record SequenceEntry(@JsonProperty("id") String id, @JsonProperty("session") String session,
            @JsonProperty("split") String split, @JsonProperty("reference") String reference,
            @JsonProperty("tags") List<String> tags, @JsonProperty("domain") String domain,
            @JsonProperty("simulator") String simulator, @JsonProperty("scenario") String scenario,
            @JsonProperty("factors") Map<String, Double> factors, @JsonProperty("environment") String environment,
            @JsonProperty("modality") String modality, @JsonProperty("ground_truth") String groundTruth) {
    }

    /**
     * Evaluation settings (see {@code EvaluationOptions}).
     *
     * @param convention lesson, evo or kitti
     * @param association interpolate, nearest or nearest_interpolated
     * @param maxDiffS max stamp difference for nearest association (s)
     * @param overlap crop or strict
     * @param alignment alignment model
     * @param rpeDelta RPE horizon in {@code rpeUnit}
     * @param rpeUnit s, frames or m
     * @param rpePairs consecutive or all_pairs
     * @param driftSegmentLengthsM drift segment lengths (m), or null without drift
     * @param driftStepFrames frames between drift segment starts, or null without drift
     */
    @JsonPropertyOrder({"convention", "association", "max_diff_s", "overlap", "alignment", "rpe_delta", "rpe_unit",
        "rpe_pairs", "drift_segment_lengths_m", "drift_step_frames"})
    public record MetricSettings(@JsonProperty("convention") String convention,
            @JsonProperty("association") String association, @JsonProperty("max_diff_s") double maxDiffS,
            @JsonProperty("overlap") String overlap, @JsonProperty("alignment") String alignment,
            @JsonProperty("rpe_delta") double rpeDelta, @JsonProperty("rpe_unit") String rpeUnit,
            @JsonProperty("rpe_pairs") String rpePairs,
            @JsonProperty("drift_segment_lengths_m") double[] driftSegmentLengthsM,
            @JsonProperty("drift_step_frames") Integer driftStepFrames) {
    }

    /**
     * @param declared the manifest's seed set Omega
     * @param common seeds every method has; all statistics use only these
     * @param deviations methods with missing or extra seeds
     */
    @JsonPropertyOrder({"declared", "common", "deviations"})
    public record Seeds(@JsonProperty("declared") List<Long> declared, @JsonProperty("common") List<Long> common,
            @JsonProperty("deviations") List<SeedDeviation> deviations) {
    }

    /**
     * @param method the method
     * @param missing declared seeds the method lacks
     * @param extra seeds beyond the declared set (not used)
     */
    @JsonPropertyOrder({"method", "missing", "extra"})
    public record SeedDeviation(@JsonProperty("method") String method, @JsonProperty("missing") List<Long> missing,
            @JsonProperty("extra") List<Long> extra) {
    }

    /**
     * @param device cpu or gpu
     * @param cores allowed CPU cores, or null
     * @param realTimeFactor required real-time factor
     * @param memoryCapMib memory cap (MiB)
     */
    @JsonPropertyOrder({"device", "cores", "real_time_factor", "memory_cap_mib"})
    public record BudgetEntry(@JsonProperty("device") String device, @JsonProperty("cores") Integer cores,
            @JsonProperty("real_time_factor") double realTimeFactor,
            @JsonProperty("memory_cap_mib") long memoryCapMib) {
    }

    /**
     * @param always failures that need no threshold
     * @param minCoverage min coverage fraction, or null
     * @param maxAteTransRmseM max ATE translation RMSE (m), or null
     * @param divergenceTransM divergence threshold on single ATE errors (m), or null
     */
    @JsonPropertyOrder({"always", "min_coverage", "max_ate_trans_rmse_m", "divergence_trans_m"})
    public record FailureSettings(@JsonProperty("always") List<String> always,
            @JsonProperty("min_coverage") Double minCoverage,
            @JsonProperty("max_ate_trans_rmse_m") Double maxAteTransRmseM,
            @JsonProperty("divergence_trans_m") Double divergenceTransM) {
    }

    /**
     * @param metric metric key (with unit)
     * @param cap c_j in the metric's unit
     * @param weight w_j
     */
    @JsonPropertyOrder({"metric", "cap", "weight"})
    public record ScoreTerm(@JsonProperty("metric") String metric, @JsonProperty("cap") double cap,
            @JsonProperty("weight") double weight) {
    }

    /**
     * @param seed seed of the bootstrap
     * @param confidenceLevel level of every interval
     * @param bootstrapResamples bootstrap resamples B
     * @param wilcoxonExactMaxN largest number of non-zero differences for the exact Wilcoxon p-value
     * @param power power 1 - beta of the planning figures
     * @param targetDifferences per metric, the mean difference whose needed number of sequences is reported
     * @param multipleComparisons adjustment of the pairwise p-values within each metric ("holm")
     * @param failureRateClustering how the clustered failure-rate interval treats seeds of one sequence
     */
    @JsonPropertyOrder({"seed", "confidence_level", "bootstrap_resamples", "wilcoxon_exact_max_n", "power",
        "target_differences", "multiple_comparisons", "failure_rate_clustering"})
    public record Analysis(@JsonProperty("seed") long seed, @JsonProperty("confidence_level") double confidenceLevel,
            @JsonProperty("bootstrap_resamples") int bootstrapResamples,
            @JsonProperty("wilcoxon_exact_max_n") int wilcoxonExactMaxN,
            @JsonProperty("power") Double power,
            @JsonProperty("target_differences") Map<String, Double> targetDifferences,
            @JsonProperty("multiple_comparisons") String multipleComparisons,
            @JsonProperty("failure_rate_clustering") String failureRateClustering) {
    }

    /**
     * @param leakage every split-leakage violation
     * @param leakageAllowed true when the suite ran despite leakage ({@code --allow-leakage})
     * @param warnings one line per hygiene problem, for people
     */
    @JsonPropertyOrder({"leakage", "leakage_allowed", "warnings"})
    public record Hygiene(@JsonProperty("leakage") List<Leak> leakage,
            @JsonProperty("leakage_allowed") boolean leakageAllowed,
            @JsonProperty("warnings") List<String> warnings) {
    }

    /**
     * @param unit session or sequence
     * @param id the session or sequence id
     * @param members per split, the sequences in that split
     */
    @JsonPropertyOrder({"unit", "id", "members"})
    public record Leak(@JsonProperty("unit") String unit, @JsonProperty("id") String id,
            @JsonProperty("members") Map<String, List<String>> members) {
    }

    /**
     * @param role manifest, reference or estimate
     * @param path path relative to the manifest's folder
     * @param sha256 SHA-256 of the bytes, lower-case hex; null when the file is missing
     */
    @JsonPropertyOrder({"role", "path", "sha256"})
    public record InputDigest(@JsonProperty("role") String role, @JsonProperty("path") String path,
            @JsonProperty("sha256") String sha256) {
    }

    /**
     * @param name method name
     * @param runs runs over the evaluated sequences and the common seeds
     * @param failures failed runs among them
     * @param failureRate failures / runs with its binomial intervals
     * @param score normalised score S over all runs (a failed run scores 0)
     * @param scorePerSequence S per sequence over the seeds
     * @param metrics per score metric, statistics over successful runs
     * @param scoreVariance the score's variance split between sequences and seeds, null when not estimable
     */
    @JsonPropertyOrder({"name", "runs", "failures", "failure_rate", "score", "score_per_sequence", "metrics",
        "score_variance"})
    public record MethodSummary(@JsonProperty("name") String name, @JsonProperty("runs") int runs,
            @JsonProperty("failures") int failures, @JsonProperty("failure_rate") Proportion failureRate,
            @JsonProperty("score") Summary score,
            @JsonProperty("score_per_sequence") List<SequenceSummary> scorePerSequence,
            @JsonProperty("metrics") List<MetricSummary> metrics,
            @JsonProperty("score_variance") VarianceSplit scoreVariance) {
    }

    /**
     * One-way random-effects split of a metric's variance over runs (ANOVA estimator), in the
     * metric's unit.
     *
     * @param sequences sequences with a value
     * @param values values in all
     * @param seedsPerSequence n0, the effective number of seeds per sequence
     * @param sequenceSd sigma_seq, between-sequence standard deviation
     * @param seedSd sigma_seed, between-seed standard deviation within a sequence
     * @param sequenceShare sigma_seq^2 / (sigma_seq^2 + sigma_seed^2), null when both are 0
     * @param advice more_seeds or more_sequences
     */
    @JsonPropertyOrder({"sequences", "values", "seeds_per_sequence", "sequence_sd", "seed_sd", "sequence_share",
        "advice"})
    public record VarianceSplit(@JsonProperty("sequences") int sequences, @JsonProperty("values") int values,
            @JsonProperty("seeds_per_sequence") double seedsPerSequence,
            @JsonProperty("sequence_sd") double sequenceSd, @JsonProperty("seed_sd") double seedSd,
            @JsonProperty("sequence_share") Double sequenceShare, @JsonProperty("advice") String advice) {
    }

    /**
     * @param estimate f / n
     * @param level confidence level
     * @param wilson Wilson score interval
     * @param clopperPearson Clopper-Pearson interval
     * @param clustered interval that treats the seeds of one sequence as a cluster (the one to quote)
     */
    @JsonPropertyOrder({"estimate", "level", "wilson", "clopper_pearson", "clustered"})
    public record Proportion(@JsonProperty("estimate") double estimate, @JsonProperty("level") double level,
            @JsonProperty("wilson") Bounds wilson, @JsonProperty("clopper_pearson") Bounds clopperPearson,
            @JsonProperty("clustered") ClusteredBounds clustered) {
    }

    /**
     * @param method korn_graubard_sequence_clusters
     * @param sequences sequences the runs cluster in
     * @param designEffect runs per independent trial, N / n*, null with one sequence
     * @param effectiveTrials n* after the degrees-of-freedom correction, null with one sequence
     * @param lower lower bound
     * @param upper upper bound
     */
    @JsonPropertyOrder({"method", "sequences", "design_effect", "effective_trials", "lower", "upper"})
    public record ClusteredBounds(@JsonProperty("method") String method, @JsonProperty("sequences") int sequences,
            @JsonProperty("design_effect") Double designEffect,
            @JsonProperty("effective_trials") Double effectiveTrials, @JsonProperty("lower") double lower,
            @JsonProperty("upper") double upper) {
    }

    /**
     * @param lower lower bound
     * @param upper upper bound
     */
    @JsonPropertyOrder({"lower", "upper"})
    public record Bounds(@JsonProperty("lower") double lower, @JsonProperty("upper") double upper) {
    }

    /**
     * Mean and sample standard deviation (K-1).
     *
     * @param n number of values
     * @param mean mean, null when n = 0
     * @param sd sample standard deviation, null when n &lt; 2
     */
    @JsonPropertyOrder({"n", "mean", "sd"})
    public record Summary(@JsonProperty("n") int n, @JsonProperty("mean") Double mean, @JsonProperty("sd") Double sd) {
    }

    /**
     * @param sequence sequence id
     * @param n successful seeds
     * @param mean mean over seeds, null when n = 0
     * @param sd sample standard deviation over seeds (K-1), null when n &lt; 2
     */
    @JsonPropertyOrder({"sequence", "n", "mean", "sd"})
    public record SequenceSummary(@JsonProperty("sequence") String sequence, @JsonProperty("n") int n,
            @JsonProperty("mean") Double mean, @JsonProperty("sd") Double sd) {
    }

    /**
     * @param metric metric key (with unit)
     * @param meanOfSequenceMeans mean over sequences of the per-sequence means, null when none
     * @param perSequence per sequence, mean and sd over seeds
     * @param variance the split of the metric's variance between sequences and seeds, null when not estimable
     */
    @JsonPropertyOrder({"metric", "mean_of_sequence_means", "per_sequence", "variance"})
    public record MetricSummary(@JsonProperty("metric") String metric,
            @JsonProperty("mean_of_sequence_means") Double meanOfSequenceMeans,
            @JsonProperty("per_sequence") List<SequenceSummary> perSequence,
            @JsonProperty("variance") VarianceSplit variance) {
    }

    /**
     * Paired comparison of two methods on one metric over the sequences where both have a value
     * (the per-sequence mean over the common seeds; each method's mean is over its own successful
     * seeds): d_s = a_s - b_s.
     *
     * @param methodA first method
     * @param methodB second method
     * @param metric metric key, or "score"
     * @param better "lower" for error metrics, "higher" for the score
     * @param n number of paired sequences
     * @param nonzeroDifferences paired sequences with d_s != 0 (the Wilcoxon test's n)
     * @param meanDifference mean of d_s, null when n = 0
     * @param tInterval t-interval of the mean difference, null when n &lt; 2
     * @param bootstrap seeded percentile bootstrap over sequences, null when n &lt; 2
     * @param wilcoxon Wilcoxon signed-rank test, null when n = 0
     * @param holm the Wilcoxon p-value adjusted by Holm's method within its family, null when n = 0
     * @param hodgesLehmann Hodges-Lehmann estimate of d with its interval, null when n = 0
     * @param wins on how many sequences A is better, equal, worse; null when n = 0
     * @param planning minimum detectable difference and sequences needed, null when n &lt; 2
     * @param test the test the conclusion rests on: none, bootstrap_descriptive, wilcoxon_exact,
     *     wilcoxon_normal_approximation or t_interval
     * @param primary which test applies at this n and number of non-zero differences, and why
     * @param perSequence the paired values
     */
    @JsonPropertyOrder({"method_a", "method_b", "metric", "better", "n", "nonzero_differences", "mean_difference",
        "t_interval", "bootstrap", "wilcoxon", "holm", "hodges_lehmann", "wins", "planning", "test", "primary",
        "per_sequence"})
    public record Comparison(@JsonProperty("method_a") String methodA, @JsonProperty("method_b") String methodB,
            @JsonProperty("metric") String metric, @JsonProperty("better") String better, @JsonProperty("n") int n,
            @JsonProperty("nonzero_differences") int nonzeroDifferences,
            @JsonProperty("mean_difference") Double meanDifference, @JsonProperty("t_interval") Bounds tInterval,
            @JsonProperty("bootstrap") Bounds bootstrap, @JsonProperty("wilcoxon") Wilcoxon wilcoxon,
            @JsonProperty("holm") HolmAdjusted holm, @JsonProperty("hodges_lehmann") HodgesLehmannEntry hodgesLehmann,
            @JsonProperty("wins") Wins wins, @JsonProperty("planning") Planning planning,
            @JsonProperty("test") String test, @JsonProperty("primary") String primary,
            @JsonProperty("per_sequence") List<Paired> perSequence) {

        /** @return a short name of the test this row rests on, with the Wilcoxon variant, for tables */
        @com.fasterxml.jackson.annotation.JsonIgnore
        public String testLabel() {
            String variant = wilcoxon == null ? "-" : wilcoxon.method().replace('_', ' ')
                    .replace("no nonzero differences", "all d = 0");
            return switch (test == null ? "" : test) {
                case "wilcoxon_exact" -> "Wilcoxon exact";
                case "wilcoxon_normal_approximation" -> "Wilcoxon normal approx.";
                case "t_interval" -> "t-interval (Wilcoxon " + variant + ")";
                case "bootstrap_descriptive" -> "bootstrap, descriptive (nz < 6)";
                case "none" -> "none (n < 2)";
                default -> "-";
            };
        }

        /** @return this comparison with its Holm-adjusted p-value */
        public Comparison withHolm(HolmAdjusted h) {
            return new Comparison(methodA, methodB, metric, better, n, nonzeroDifferences, meanDifference, tInterval,
                    bootstrap, wilcoxon, h, hodgesLehmann, wins, planning, test, primary, perSequence);
        }
    }

    /**
     * @param family the tests adjusted together (the pairwise Wilcoxon tests of one metric)
     * @param m number of tests in the family
     * @param pAdjusted Holm-adjusted p-value
     */
    @JsonPropertyOrder({"family", "m", "p_adjusted"})
    public record HolmAdjusted(@JsonProperty("family") String family, @JsonProperty("m") int m,
            @JsonProperty("p_adjusted") double pAdjusted) {
    }

    /**
     * @param estimate median of the Walsh averages of d (metric's unit)
     * @param lower lower bound
     * @param upper upper bound
     * @param level requested level
     * @param achievedLevel level the discrete exact interval attains
     * @param method exact or asymptotic
     */
    @JsonPropertyOrder({"estimate", "lower", "upper", "level", "achieved_level", "method"})
    public record HodgesLehmannEntry(@JsonProperty("estimate") double estimate, @JsonProperty("lower") double lower,
            @JsonProperty("upper") double upper, @JsonProperty("level") double level,
            @JsonProperty("achieved_level") double achievedLevel, @JsonProperty("method") String method) {
    }

    /**
     * @param aBetter sequences on which A is better
     * @param ties sequences with d_s = 0
     * @param bBetter sequences on which B is better
     * @param shareABetter aBetter / n
     */
    @JsonPropertyOrder({"a_better", "ties", "b_better", "share_a_better"})
    public record Wins(@JsonProperty("a_better") int aBetter, @JsonProperty("ties") int ties,
            @JsonProperty("b_better") int bBetter, @JsonProperty("share_a_better") double shareABetter) {
    }

    /**
     * @param sdDifference s_d, standard deviation of the paired differences (metric's unit)
     * @param power power 1 - beta
     * @param minDetectableDifference delta_min at this n, level and power (metric's unit)
     * @param targetDifference the difference asked for (--detect), null when none
     * @param sequencesNeeded sequences needed to detect it, null when none asked or more than 10^6
     */
    @JsonPropertyOrder({"sd_difference", "power", "min_detectable_difference", "target_difference",
        "sequences_needed"})
    public record Planning(@JsonProperty("sd_difference") double sdDifference, @JsonProperty("power") double power,
            @JsonProperty("min_detectable_difference") double minDetectableDifference,
            @JsonProperty("target_difference") Double targetDifference,
            @JsonProperty("sequences_needed") Integer sequencesNeeded) {
    }

    /**
     * Many methods at once on one metric: the Friedman test over the sequences where every method
     * has a value, average ranks (1 = best) and the groups of the average-rank diagram.
     *
     * @param metric metric key, or "score"
     * @param better lower or higher
     * @param n sequences where every method has a value (the blocks)
     * @param methods methods with their average ranks, in report order
     * @param friedman Friedman chi-square test, null when n &lt; 2
     * @param imanDavenport Iman-Davenport F test, null when n &lt; 2
     * @param family the Holm family the groups come from
     * @param alpha significance level of the groups, 1 - confidence
     * @param groups methods (in rank order) no pair of which differs significantly after Holm
     */
    @JsonPropertyOrder({"metric", "better", "n", "methods", "friedman", "iman_davenport", "family", "alpha",
        "groups"})
    public record Ranking(@JsonProperty("metric") String metric, @JsonProperty("better") String better,
            @JsonProperty("n") int n, @JsonProperty("methods") List<RankedMethod> methods,
            @JsonProperty("friedman") RankTest friedman, @JsonProperty("iman_davenport") RankTest imanDavenport,
            @JsonProperty("family") String family, @JsonProperty("alpha") double alpha,
            @JsonProperty("groups") List<List<String>> groups) {
    }

    /**
     * @param name method
     * @param averageRank average rank over the blocks (1 = best), null when n = 0
     */
    @JsonPropertyOrder({"name", "average_rank"})
    public record RankedMethod(@JsonProperty("name") String name, @JsonProperty("average_rank") Double averageRank) {
    }

    /**
     * @param statistic chi2_F or F_F; null when infinite (every sequence ranks the methods alike)
     * @param df degrees of freedom (numerator for F)
     * @param dfDenominator denominator degrees of freedom of F, null for chi-square
     * @param pValue upper-tail p-value
     */
    @JsonPropertyOrder({"statistic", "df", "df_denominator", "p_value"})
    public record RankTest(@JsonProperty("statistic") Double statistic, @JsonProperty("df") int df,
            @JsonProperty("df_denominator") Integer dfDenominator, @JsonProperty("p_value") double pValue) {
    }

    /**
     * @param n non-zero differences
     * @param zeros zero differences dropped
     * @param wPlus W+
     * @param wMinus W-
     * @param pValue two-sided p-value
     * @param method exact, normal_approximation or no_nonzero_differences
     */
    @JsonPropertyOrder({"n", "zeros", "w_plus", "w_minus", "p_value", "method"})
    public record Wilcoxon(@JsonProperty("n") int n, @JsonProperty("zeros") int zeros,
            @JsonProperty("w_plus") double wPlus, @JsonProperty("w_minus") double wMinus,
            @JsonProperty("p_value") double pValue, @JsonProperty("method") String method) {
    }

    /**
     * @param sequence sequence id
     * @param a value of method A
     * @param b value of method B
     * @param difference a - b
     */
    @JsonPropertyOrder({"sequence", "a", "b", "difference"})
    public record Paired(@JsonProperty("sequence") String sequence, @JsonProperty("a") double a,
            @JsonProperty("b") double b, @JsonProperty("difference") double difference) {
    }

    /**
     * One (method, sequence, seed) run.
     *
     * @param method method name
     * @param sequence sequence id
     * @param seed seed
     * @param split split of the sequence
     * @param estimate estimate file, relative to the manifest
     * @param status ok or failed
     * @param failure why the run failed, null when ok
     * @param coverage fraction of the reference's time span covered by the estimate, null when unread
     * @param metrics the score metrics (keys with units), null values when unavailable
     * @param score normalised score S (0 for a failed run)
     * @param evaluation the engine's report, null when the estimate could not be evaluated
     */
    @JsonPropertyOrder({"method", "sequence", "seed", "split", "estimate", "status", "failure", "coverage", "metrics",
        "score", "evaluation"})
    public record RunEntry(@JsonProperty("method") String method, @JsonProperty("sequence") String sequence,
            @JsonProperty("seed") long seed, @JsonProperty("split") String split,
            @JsonProperty("estimate") String estimate, @JsonProperty("status") String status,
            @JsonProperty("failure") RunFailure failure, @JsonProperty("coverage") Double coverage,
            @JsonProperty("metrics") Map<String, Double> metrics, @JsonProperty("score") double score,
            @JsonProperty("evaluation") EvaluationReport evaluation) implements java.io.Serializable {

        /** @return true when the run succeeded */
        public boolean ok() {
            return "ok".equals(status);
        }
    }

    /**
     * @param reason reason key (missing_estimate, unreadable_estimate, evaluation_refused,
     *     low_coverage, ate_above_threshold, diverged)
     * @param detail one line for a person
     */
    @JsonPropertyOrder({"reason", "detail"})
    public record RunFailure(@JsonProperty("reason") String reason, @JsonProperty("detail") String detail) implements java.io.Serializable {
    }
}
