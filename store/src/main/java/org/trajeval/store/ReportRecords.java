package org.trajeval.store;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.security.NoSuchAlgorithmException;
import java.time.Instant;
import java.time.format.DateTimeParseException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.HexFormat;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.trajeval.core.protocol.RunMetric;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReportFiles;

/**
 * Turns report files (the source of truth) into store rows: a suite {@code report.json} gives one
 * row per (method, sequence, seed) run, a pipeline report {@code reports/RUN_ID.json} one row, an
 * eval report ({@code eval --out}) one row.
 *
 * <p>Row keys: a pipeline row's key is SHA-256("pipeline", content_sha256, labels); a suite row's
 * is SHA-256("suite", dataset, method, sequence, seed, the estimate's and the reference's
 * SHA-256, the metric settings and score terms, labels). The same report recorded twice, by any
 * writer, gives the same keys.
 */
public final class ReportRecords {
    /** Schema name of a pipeline report. */
    public static final String PIPELINE_SCHEMA = "trajeval.pipeline.run";
    private static final ObjectMapper MAPPER = new ObjectMapper();

    private ReportRecords() {
    }

    /** What a JSON file holds. */
    public enum Kind {
        /** A suite report.json. */
        SUITE,
        /** A pipeline run report. */
        PIPELINE,
        /** A {@code trajeval eval} report. */
        EVALUATION,
        /** Some other JSON (left alone by imports). */
        OTHER
    }

    /**
     * @param json the file's text
     * @param source the file name, for messages
     * @return what the file holds
     * @throws StoreException BAD_REPORT when the text is not JSON
     */
    public static Kind kind(String json, String source) {
        JsonNode schema = tree(json, source).get("schema");
        String s = schema == null ? "" : schema.asText();
        if (SuiteReport.SCHEMA.equals(s)) {
            return Kind.SUITE;
        }
        if (EvaluationReport.SCHEMA.equals(s)) {
            return Kind.EVALUATION;
        }
        return PIPELINE_SCHEMA.equals(s) ? Kind.PIPELINE : Kind.OTHER;
    }

    /**
     * @param json a pipeline report's text
     * @param source the file, for messages and the row's source
     * @param labels labels to add (a label the report holds itself wins)
     * @throws StoreException BAD_REPORT when it is not a pipeline report
     */
    public static RunRecord fromPipeline(String json, String source, Labels labels) {
        JsonNode n = tree(json, source);
        if (!PIPELINE_SCHEMA.equals(text(n, "schema"))) {
            throw bad(source, "not a pipeline report (schema " + PIPELINE_SCHEMA + " expected)", null);
        }
        if (text(n, "content_sha256") == null || n.get("evaluation") == null) {
            throw bad(source, "a pipeline report needs content_sha256, processed_at and evaluation", null);
        }
        processedAt(text(n, "processed_at"), source); // its refusal before the evaluation's, as always
        EvaluationReport evaluation;
        try {
            evaluation = ReportJson.parseEvaluation(n.get("evaluation").toString());
        } catch (IllegalArgumentException e) {
            throw bad(source, e.getMessage(), e);
        }
        Map<String, String> tags = new LinkedHashMap<>();
        JsonNode t = n.get("tags");
        if (t != null && t.isObject()) {
            for (Iterator<Map.Entry<String, JsonNode>> it = t.fields(); it.hasNext();) {
                Map.Entry<String, JsonNode> e = it.next();
                tags.put(e.getKey(), e.getValue().asText());
            }
        }
        Map<String, Double> factors = new LinkedHashMap<>();
        JsonNode fn = n.get("factors");
        if (fn != null && fn.isObject()) {
            fn.fields().forEachRemaining(e -> factors.put(e.getKey(), e.getValue().asDouble()));
        }
        JsonNode res = n.get("resources");
        Double wall = null;
        Double mem = null;
        if (res != null && res.isObject()) {
            wall = res.hasNonNull("wall_time_s") ? res.get("wall_time_s").asDouble() : null;
            mem = res.hasNonNull("peak_memory_mib") ? res.get("peak_memory_mib").asDouble() : null;
        }
        JsonNode seed = n.get("seed");
        JsonNode version = n.get("run_version");
        return fromPipeline(new PipelineFields(text(n, "run_id"), version == null ? null : version.asInt(),
                text(n, "content_sha256"), text(n, "processed_at"), text(n, "robot_id"), text(n, "site"),
                text(n, "sequence"), text(n, "method"), text(n, "software_version"),
                seed == null || seed.isNull() ? null : Long.valueOf(seed.asLong()), tags, factors, wall, mem,
                text(n, "domain"), text(n, "scenario"), text(n, "simulator"), text(n, "environment"),
                text(n, "modality"), text(n, "ground_truth"), evaluation), source, labels);
    }

    /**
     * One row for one pipeline report, from its fields: the report file's (above) or the report the
     * pipeline has in hand, the same row either way.
     *
     * @param f the report's fields
     * @param source the report file, for messages and the row's source
     * @param labels labels to add (a label the report holds itself wins)
     * @throws StoreException BAD_REPORT when content_sha256, processed_at or the evaluation is missing
     */
    public static RunRecord fromPipeline(PipelineFields f, String source, Labels labels) {
        String content = f.contentSha256();
        if (content == null || f.evaluation() == null) {
            throw bad(source, "a pipeline report needs content_sha256, processed_at and evaluation", null);
        }
        Instant at = processedAt(f.processedAt(), source);
        Map<String, Double> metrics = metrics(f.evaluation());
        Map<String, String> tags = new LinkedHashMap<>(labels.tags());
        if (f.tags() != null) {
            tags.putAll(f.tags());
        }
        String key = pipelineKey(content, labels);
        return new RunRecord(key, "pipeline", f.runId(), f.runVersion(), content, null,
                labels.column("robot", f.robotId()), labels.column("site", f.site()),
                labels.column("route", f.sequence()), labels.column("method", f.method()),
                labels.column("software_version", f.softwareVersion()),
                f.seed() == null ? labelSeed(labels) : f.seed(), at, true, null, metrics, source, tags,
                new RunDescription(f.domain(), f.scenario(), f.simulator(), f.environment(), f.modality(),
                        f.groundTruth(), factors(f.factors()), f.wallTimeS(), f.peakMemoryMib()));
    }

    /** @return {@code processed_at} as an instant; StoreException BAD_REPORT when missing or malformed */
    private static Instant processedAt(String processed, String source) {
        if (processed == null) {
            throw bad(source, "a pipeline report needs content_sha256, processed_at and evaluation", null);
        }
        try {
            return Instant.parse(processed);
        } catch (DateTimeParseException e) {
            throw bad(source, "processed_at must be an ISO-8601 UTC time, found \"" + processed + "\"", e);
        }
    }

    /** @return a suite run's description: its sequence's fields and its measured resources */
    private static RunDescription description(SuiteReport.SequenceEntry q,
            org.trajeval.core.report.BudgetReport.RunBudget b) {
        if (q == null) {
            return RunDescription.NONE;
        }
        return new RunDescription(q.domain(), q.scenario(), q.simulator(), q.environment(), q.modality(),
                q.groundTruth(), factors(q.factors()), b == null ? null : b.wallTimeS(),
                b == null ? null : b.peakMemoryMib());
    }

    /** @return factor levels as {@code name=level;name=level}, or null without factors */
    private static String factors(java.util.Map<String, Double> f) {
        if (f == null || f.isEmpty()) {
            return null;
        }
        List<String> out = new ArrayList<>();
        new java.util.TreeMap<>(f).forEach((k, v) -> out.add(k + "=" + v));
        return String.join(";", out);
    }

    /** @return the seed label, or null ({@link Labels#parse} checked it is a whole number) */
    private static Long labelSeed(Labels labels) {
        String seed = labels.columns().get("seed");
        return seed == null ? null : Long.valueOf(Long.parseLong(seed));
    }

    /** @return the run metrics of an evaluation that are finite, by column */
    private static Map<String, Double> metrics(EvaluationReport evaluation) {
        Map<String, Double> metrics = new HashMap<>();
        for (RunMetric m : RunMetric.values()) {
            double v = m.of(evaluation);
            if (Double.isFinite(v)) {
                metrics.put(m.key(), v);
            }
        }
        return metrics;
    }

    /**
     * One row for one {@code trajeval eval} report (schema {@code trajeval.evaluation}), the same
     * whether {@code eval --db} records it or {@code db import} reads its {@code --out} file.
     * Key: SHA-256("eval", the report re-serialised canonically, labels); the report names both
     * inputs with their SHA-256 and every setting, so the same evaluation recorded again is a no-op.
     * Robot, site, route, method, seed and software version come from the labels.
     *
     * @param json the report's text
     * @param source the report file, or a description of the inputs, for the row's source
     * @param recordedAt when it was evaluated (an imported file: its modification time)
     * @throws StoreException BAD_REPORT when it is no evaluation report
     */
    public static RunRecord fromEvaluation(String json, String source, Instant recordedAt, Labels labels) {
        EvaluationReport evaluation;
        try {
            evaluation = ReportJson.parseEvaluation(json);
        } catch (IllegalArgumentException e) {
            throw bad(source, e.getMessage(), e);
        }
        if (!EvaluationReport.SCHEMA.equals(evaluation.schema())) {
            throw bad(source, "not an evaluation report (schema " + EvaluationReport.SCHEMA + " expected)", null);
        }
        String key = sha256("eval", ReportJson.toJson(evaluation), labels.canonical());
        return new RunRecord(key, "eval", null, null, null, null, labels.columns().get("robot"),
                labels.columns().get("site"), labels.columns().get("route"), labels.columns().get("method"),
                labels.columns().get("software_version"), labelSeed(labels), recordedAt, true, null,
                metrics(evaluation), source, labels.tags());
    }

    /** @return the row key of a pipeline report with this content hash and these labels */
    public static String pipelineKey(String contentSha256, Labels labels) {
        return sha256("pipeline", contentSha256, labels.canonical());
    }

    /**
     * @param report a suite report
     * @param source the report file, for the rows' source
     * @param recordedAt when the suite ran (the report holds no time: it is byte-reproducible)
     * @param labels labels of every run (software_version, robot, site, tags)
     * @return one row per run
     */
    public static List<RunRecord> fromSuite(SuiteReport report, String source, Instant recordedAt, Labels labels) {
        Map<String, String> digests = new HashMap<>();
        for (SuiteReport.InputDigest d : report.inputs()) {
            digests.put(d.role() + ":" + d.path(), d.sha256());
        }
        Map<String, String> references = new HashMap<>();
        for (SuiteReport.SequenceEntry s : report.protocol().sequences()) {
            references.put(s.id(), digests.get("reference:" + s.reference()));
        }
        String settings = ReportJson.toJson(report.protocol().metrics()) + ReportJson.toJson(report.protocol().score());
        Map<String, SuiteReport.SequenceEntry> sequences = new HashMap<>();
        report.protocol().sequences().forEach(q -> sequences.put(q.id(), q));
        Map<String, org.trajeval.core.report.BudgetReport.RunBudget> budgets = new HashMap<>();
        if (report.budgets() != null) {
            report.budgets().runs().forEach(b -> budgets.put(b.method() + "/" + b.sequence() + "/" + b.seed(), b));
        }
        List<RunRecord> out = new ArrayList<>();
        for (SuiteReport.RunEntry r : report.runs()) {
            String key = sha256("suite", report.protocol().dataset(), r.method(), r.sequence(), Long.toString(r.seed()),
                    String.valueOf(digests.get("estimate:" + r.estimate())), String.valueOf(references.get(r.sequence())),
                    settings, labels.canonical());
            Map<String, Double> metrics = new HashMap<>();
            if (r.metrics() != null) {
                r.metrics().forEach((k, v) -> {
                    if (v != null && StoredMetric.keys().contains(k)) {
                        metrics.put(k, v);
                    }
                });
            }
            if (r.coverage() != null) {
                metrics.put(StoredMetric.COVERAGE, r.coverage());
            }
            metrics.put(StoredMetric.SCORE, r.score());
            out.add(new RunRecord(key, "suite", r.method() + "/" + r.sequence() + "/" + r.seed(), null, null,
                    report.protocol().dataset(), labels.columns().get("robot"), labels.columns().get("site"),
                    r.sequence(), r.method(), labels.columns().get("software_version"), r.seed(), recordedAt, r.ok(),
                    r.failure() == null ? null : r.failure().reason(), metrics, source, labels.tags(),
                    description(sequences.get(r.sequence()), budgets.get(r.method() + "/" + r.sequence() + "/"
                            + r.seed()))));
        }
        return out;
    }

    /** @return the suite report in {@code json}; StoreException BAD_REPORT when it is none */
    public static SuiteReport parseSuite(String json, String source) {
        try {
            return SuiteReportFiles.parse(json, source);
        } catch (IllegalArgumentException e) {
            throw bad(source, e.getMessage().startsWith(source) ? e.getMessage().substring(source.length() + 2)
                    : e.getMessage(), e);
        }
    }

    private static JsonNode tree(String json, String source) {
        try {
            JsonNode n = MAPPER.readTree(json);
            if (n == null || !n.isObject()) {
                throw bad(source, "expected a JSON object", null);
            }
            return n;
        } catch (JsonProcessingException e) {
            throw bad(source, "not JSON: " + e.getOriginalMessage(), e);
        }
    }

    private static String text(JsonNode n, String field) {
        JsonNode v = n.get(field);
        return v == null || v.isNull() ? null : v.asText();
    }

    private static StoreException bad(String source, String what, Throwable cause) {
        return new StoreException(StoreException.Problem.BAD_REPORT, source + ": " + what, cause);
    }

    static String sha256(String... parts) {
        try {
            MessageDigest md = MessageDigest.getInstance("SHA-256");
            for (String p : parts) {
                md.update(p.getBytes(StandardCharsets.UTF_8));
                md.update((byte) 0);
            }
            return HexFormat.of().formatHex(md.digest());
        } catch (NoSuchAlgorithmException e) {
            throw new IllegalStateException("the JDK has no SHA-256", e);
        }
    }
}
