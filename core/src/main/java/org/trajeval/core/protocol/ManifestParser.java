package org.trajeval.core.protocol;

import com.fasterxml.jackson.core.JacksonException;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.Iterator;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.StrictMappers;
import org.trajeval.core.io.TextFiles;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.RunField;
import org.trajeval.core.options.RunMetadata;
import org.trajeval.core.options.Setting;
import org.trajeval.core.options.SettingText;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.options.SettingsTree;

/**
 * Reads a suite manifest (YAML) strictly: every unknown key, missing key, wrong type and
 * inconsistency is refused with an {@link InputException} whose {@code column} is the key path
 * (e.g. {@code methods[1].estimates}) and whose detail says what was expected. Paths must be
 * relative and stay inside the manifest's folder ({@link InputProblem#PATH_ESCAPES}). Jackson
 * stays inside this class.
 *
 * <p>Example:
 * <pre>
 * format: trajeval.suite-manifest
 * version: 1
 * name: demo
 * seeds: [1, 2, 3]
 * sequences:
 *   - {id: seq01, session: s01, reference: data/seq01/gt.csv, split: test, tags: [indoor]}
 * methods:
 *   - {name: alpha, estimates: "runs/{method}/{sequence}/seed{seed}.csv"}
 * metrics: {convention: lesson, alignment: se2, rpe: {delta: 1.0, unit: s}}   # any key of Setting
 * failure: {min_coverage: 0.9, max_ate_trans_rmse_m: 5.0}
 * score:
 *   - {metric: ate_trans_rmse_m, cap: 2.0, weight: 0.5}
 *   - {metric: rpe_trans_rmse_m, cap: 0.8, weight: 0.5}
 * budget: {device: cpu, cores: 4, real_time_factor: 1.0, memory_cap_mib: 4096}
 * resources: resources.csv     # optional: method,sequence,seed,wall_time_s,peak_memory_mib per run
 * </pre>
 * A sequence may also carry the description fields of {@link RunField} ({@code domain: sim},
 * {@code scenario: corridor}, {@code factors: {obstacle_density: 0.4}}, ...).
 */
public final class ManifestParser {
    private static final Pattern ID = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]*");
    private static final Pattern PLACEHOLDER = Pattern.compile("\\{([^}]*)}");
    private static final Set<String> PLACEHOLDERS = Set.of("method", "sequence", "seed");
    private static final ObjectMapper TREE = new ObjectMapper();

    /** Largest manifest read (bytes): 16 MiB, far above any real suite. */
    static final long MAX_MANIFEST_BYTES = 16L << 20;

    private final ObjectMapper yaml = StrictMappers.yaml();

    /**
     * Reads and checks the manifest at {@code file}.
     *
     * @throws InputException on any problem, naming the key path
     */
    public SuiteManifest read(Path file) {
        String source = file.toString();
        return parse(TextFiles.readUtf8(file, "manifest", MAX_MANIFEST_BYTES), source);
    }

    /**
     * Parses manifest text; {@code source} names it in errors.
     *
     * @throws InputException on any problem, naming the key path
     */
    public SuiteManifest parse(String text, String source) {
        JsonNode root;
        try {
            root = yaml.readTree(text);
        } catch (JacksonException e) {
            long line = e.getLocation() == null ? 0 : e.getLocation().getLineNr();
            throw new InputException(source, Math.max(0, line), null, InputProblem.INVALID_CONFIGURATION,
                    "manifest is not valid YAML: " + e.getOriginalMessage(), null, e);
        }
        if (root == null || root.isMissingNode() || root.isNull()) {
            throw new InputException(source, 0, null, InputProblem.EMPTY, "manifest is empty", null);
        }
        return new Walk(source).manifest(new Node(root, ""));
    }

    /** A YAML node and its key path. */
    private record Node(JsonNode json, String path) {
        String child(String key) {
            return path.isEmpty() ? key : path + "." + key;
        }
    }

    /** Walks the tree, refusing with the source name. */
    private static final class Walk {
        private final String source;

        Walk(String source) {
            this.source = source;
        }

        InputException bad(String path, String expected, JsonNode found) {
            return new InputException(source, 0, path, InputProblem.INVALID_CONFIGURATION,
                    (path.isEmpty() ? "manifest" : "'" + path + "'") + ": " + expected,
                    found == null ? null : describe(found));
        }

        InputException bad(String path, String expected) {
            return bad(path, expected, null);
        }

        static String describe(JsonNode n) {
            if (n.isTextual()) {
                return n.asText();
            }
            if (n.isObject()) {
                return "a mapping";
            }
            if (n.isArray()) {
                return "a list";
            }
            return n.toString();
        }

        void allowOnly(Node n, String... keys) {
            if (!n.json().isObject()) {
                throw bad(n.path(), "expected a mapping with keys " + String.join(", ", keys), n.json());
            }
            Set<String> allowed = Set.of(keys);
            Iterator<String> it = n.json().fieldNames();
            while (it.hasNext()) {
                String k = it.next();
                if (!allowed.contains(k)) {
                    throw bad(n.child(k), "unknown key; expected one of " + String.join(", ", new TreeSet<>(allowed)));
                }
            }
        }

        Node required(Node n, String key) {
            JsonNode c = n.json().get(key);
            if (c == null || c.isNull()) {
                throw bad(n.child(key), "required key is missing");
            }
            return new Node(c, n.child(key));
        }

        Node optional(Node n, String key) {
            JsonNode c = n.json().get(key);
            return c == null || c.isNull() ? null : new Node(c, n.child(key));
        }

        String text(Node n, String what) {
            if (!n.json().isTextual() || n.json().asText().isBlank()) {
                throw bad(n.path(), "expected " + what, n.json());
            }
            return n.json().asText();
        }

        String id(Node n, String what) {
            String s = n.json().isNumber() ? n.json().asText() : text(n, what);
            if (!ID.matcher(s).matches()) {
                throw bad(n.path(), "expected " + what + " made of letters, digits, '.', '_', '-' (not starting with"
                        + " '.', '_' or '-')", n.json());
            }
            return s;
        }

        double number(Node n, String what) {
            if (!n.json().isNumber() || !Double.isFinite(n.json().asDouble())) {
                throw bad(n.path(), "expected " + what, n.json());
            }
            return n.json().asDouble();
        }

        long integer(Node n, String what) {
            if (!n.json().isIntegralNumber() || !n.json().canConvertToLong()) {
                throw bad(n.path(), "expected " + what, n.json());
            }
            return n.json().asLong();
        }

        List<Node> list(Node n, String what, boolean nonEmpty) {
            if (!n.json().isArray()) {
                throw bad(n.path(), "expected a list of " + what, n.json());
            }
            if (nonEmpty && n.json().isEmpty()) {
                throw bad(n.path(), "expected a non-empty list of " + what, n.json());
            }
            List<Node> out = new ArrayList<>();
            for (int i = 0; i < n.json().size(); i++) {
                out.add(new Node(n.json().get(i), n.path() + "[" + i + "]"));
            }
            return out;
        }

        /** A relative path that stays inside the manifest folder. */
        String relativePath(Node n, String value) {
            String v = value.replace('\\', '/');
            Path p = Path.of(v);
            if (p.isAbsolute() || v.startsWith("/") || v.matches("^[A-Za-z]:.*")) {
                throw new InputException(source, 0, n.path(), InputProblem.PATH_ESCAPES,
                        "'" + n.path() + "': expected a path relative to the manifest's folder", value);
            }
            Path base = Path.of("/manifest-folder");
            if (!base.resolve(p).normalize().startsWith(base)) {
                throw new InputException(source, 0, n.path(), InputProblem.PATH_ESCAPES,
                        "'" + n.path() + "': path leaves the manifest's folder", value);
            }
            return v;
        }

        SuiteManifest manifest(Node root) {
            allowOnly(root, "format", "version", "name", "seeds", "sequences", "methods", "evaluated_splits",
                    "metrics", "failure", "score", "budget", "resources");
            Node format = required(root, "format");
            if (!SuiteManifest.FORMAT.equals(format.json().asText())) {
                throw bad(format.path(), "expected " + SuiteManifest.FORMAT, format.json());
            }
            Node version = required(root, "version");
            if (integer(version, "an integer") != SuiteManifest.FORMAT_VERSION) {
                throw bad(version.path(), "expected manifest version " + SuiteManifest.FORMAT_VERSION, version.json());
            }
            String name = id(required(root, "name"), "a benchmark name");
            List<Long> seeds = seeds(required(root, "seeds"));
            List<SequenceSpec> sequences = sequences(required(root, "sequences"));
            List<MethodSpec> methods = methods(required(root, "methods"), seeds);
            List<Split> splits = List.of(Split.values());
            Node es = optional(root, "evaluated_splits");
            if (es != null) {
                Set<Split> set = new LinkedHashSet<>();
                for (Node s : list(es, "splits (train, val, test)", true)) {
                    Split sp = Split.fromKey(s.json().asText());
                    if (sp == null || !s.json().isTextual()) {
                        throw bad(s.path(), "expected one of train, val, test", s.json());
                    }
                    if (!set.add(sp)) {
                        throw bad(s.path(), "split listed twice", s.json());
                    }
                }
                splits = new ArrayList<>(new TreeSet<>(set));
                boolean any = sequences.stream().anyMatch(q -> set.contains(q.split()));
                if (!any) {
                    throw bad(es.path(), "no sequence belongs to the evaluated splits");
                }
            }
            SettingValues metrics = SettingValues.of(settings(required(root, "metrics")), source);
            for (SequenceSpec s : sequences) {
                for (MethodSpec ms : methods) {
                    check(check(metrics, s.settings()), ms.settings());
                }
            }
            FailureDefinition failure = failure(optional(root, "failure"));
            NormalisedScore score = score(required(root, "score"), metrics);
            Budget budget = budget(required(root, "budget"));
            Node res = optional(root, "resources");
            String resources = res == null ? null : relativePath(res, text(res, "a resources CSV file path"));
            return new SuiteManifest(name, sequences, methods, seeds, splits, metrics, failure, score, budget,
                    resources);
        }

        List<Long> seeds(Node n) {
            TreeSet<Long> out = new TreeSet<>();
            for (Node s : list(n, "integer seeds", true)) {
                long v = integer(s, "an integer seed");
                if (!out.add(v)) {
                    throw bad(s.path(), "seed listed twice", s.json());
                }
            }
            return new ArrayList<>(out);
        }

        List<SequenceSpec> sequences(Node n) {
            List<SequenceSpec> out = new ArrayList<>();
            Set<String> ids = new HashSet<>();
            for (Node s : list(n, "sequences", true)) {
                List<String> keys = new ArrayList<>(List.of("id", "session", "reference", "split", "tags", "settings"));
                keys.addAll(RunField.keys());
                allowOnly(s, keys.toArray(new String[0]));
                Node idNode = required(s, "id");
                String id = id(idNode, "a sequence id");
                if (!ids.add(id)) {
                    throw bad(idNode.path(), "sequence id must be unique", idNode.json());
                }
                String session = id(required(s, "session"), "a session id");
                Node ref = required(s, "reference");
                String reference = relativePath(ref, text(ref, "a reference file path"));
                Node splitNode = required(s, "split");
                Split split = splitNode.json().isTextual() ? Split.fromKey(splitNode.json().asText()) : null;
                if (split == null) {
                    throw bad(splitNode.path(), "expected one of train, val, test", splitNode.json());
                }
                List<String> tags = new ArrayList<>();
                Node tagNode = optional(s, "tags");
                if (tagNode != null) {
                    for (Node t : list(tagNode, "tags", false)) {
                        tags.add(text(t, "a tag"));
                    }
                }
                Node set = optional(s, "settings");
                @SuppressWarnings("unchecked")
                Map<String, Object> fields = TREE.convertValue(s.json(), Map.class);
                RunMetadata about = RunMetadata.parse(fields, s.path(), source);
                out.add(new SequenceSpec(id, session, reference, split, tags, set == null ? List.of() : settings(set),
                        about));
            }
            return out;
        }

        List<MethodSpec> methods(Node n, List<Long> suiteSeeds) {
            List<MethodSpec> out = new ArrayList<>();
            Set<String> names = new HashSet<>();
            for (Node m : list(n, "methods", true)) {
                allowOnly(m, "name", "estimates", "seeds", "settings");
                Node nameNode = required(m, "name");
                String name = id(nameNode, "a method name");
                if (!names.add(name)) {
                    throw bad(nameNode.path(), "method name must be unique", nameNode.json());
                }
                Node est = required(m, "estimates");
                String pattern = text(est, "a path pattern such as runs/{method}/{sequence}/seed{seed}.csv");
                Matcher mt = PLACEHOLDER.matcher(pattern);
                Set<String> used = new HashSet<>();
                while (mt.find()) {
                    if (!PLACEHOLDERS.contains(mt.group(1))) {
                        throw bad(est.path(), "unknown placeholder {" + mt.group(1)
                                + "}; expected {method}, {sequence} or {seed}", est.json());
                    }
                    used.add(mt.group(1));
                }
                if (!used.contains("sequence")) {
                    throw bad(est.path(), "pattern must contain {sequence} (one file per sequence)", est.json());
                }
                Node seedNode = optional(m, "seeds");
                List<Long> seeds = seedNode == null ? suiteSeeds : seeds(seedNode);
                if (seeds.size() > 1 && !used.contains("seed")) {
                    throw bad(est.path(), "pattern must contain {seed} when there is more than one seed", est.json());
                }
                relativePath(est, pattern.replace("{method}", name).replace("{sequence}", "x").replace("{seed}", "0"));
                Node set = optional(m, "settings");
                out.add(new MethodSpec(name, pattern, seeds, set == null ? List.of() : settings(set)));
            }
            return out;
        }

        /**
         * The evaluation settings of {@code metrics} (or an entry's {@code settings}): every key of
         * the settings table ({@link Setting}), nested mappings as shorthand ({@code rpe: {delta: 1}}).
         */
        List<SettingText> settings(Node n) {
            if (!n.json().isObject()) {
                throw bad(n.path(), "expected a mapping of settings (" + Setting.knownKeys() + ")", n.json());
            }
            @SuppressWarnings("unchecked")
            Map<String, Object> tree = TREE.convertValue(n.json(), Map.class);
            return SettingsTree.flatten(tree, n.path(), source);
        }

        /** Checks the merged settings of one run once, so a bad combination is refused at intake. */
        SettingValues check(SettingValues base, List<SettingText> more) {
            return base.with(more, source);
        }

        FailureDefinition failure(Node n) {
            if (n == null) {
                return FailureDefinition.NONE;
            }
            allowOnly(n, "min_coverage", "max_ate_trans_rmse_m", "divergence_trans_m", "budget", "breakdown_rate");
            Double cov = null;
            Node c = optional(n, "min_coverage");
            if (c != null) {
                cov = number(c, "a fraction in [0, 1]");
                if (cov < 0.0 || cov > 1.0) {
                    throw bad(c.path(), "expected a fraction in [0, 1]", c.json());
                }
            }
            Double ate = positive(optional(n, "max_ate_trans_rmse_m"), "a distance > 0 (m)");
            Double div = positive(optional(n, "divergence_trans_m"), "a distance > 0 (m)");
            FailureDefinition.BudgetPolicy policy = FailureDefinition.BudgetPolicy.FAIL;
            Node b = optional(n, "budget");
            if (b != null) {
                String w = b.json().isTextual() ? b.json().asText() : "";
                if (!w.equals("fail") && !w.equals("warn")) {
                    throw bad(b.path(), "expected fail or warn (what a run over the budget is)", b.json());
                }
                policy = w.equals("warn") ? FailureDefinition.BudgetPolicy.WARN : FailureDefinition.BudgetPolicy.FAIL;
            }
            double rate = FailureDefinition.DEFAULT_BREAKDOWN_RATE;
            Node r = optional(n, "breakdown_rate");
            if (r != null) {
                rate = number(r, "a failure rate in (0, 1]");
                if (!(rate > 0.0 && rate <= 1.0)) {
                    throw bad(r.path(), "expected a failure rate in (0, 1]", r.json());
                }
            }
            return new FailureDefinition(cov, ate, div, policy, rate);
        }

        Double positive(Node n, String what) {
            if (n == null) {
                return null;
            }
            double v = number(n, what);
            if (!(v > 0.0)) {
                throw bad(n.path(), "expected " + what, n.json());
            }
            return v;
        }

        NormalisedScore score(Node n, SettingValues metrics) {
            List<NormalisedScore.Term> terms = new ArrayList<>();
            double sum = 0.0;
            Set<RunMetric> seen = new HashSet<>();
            List<String> keys = new ArrayList<>();
            for (RunMetric m : RunMetric.values()) {
                keys.add(m.key());
            }
            for (Node t : list(n, "score terms {metric, cap, weight}", true)) {
                allowOnly(t, "metric", "cap", "weight");
                Node mn = required(t, "metric");
                RunMetric m = mn.json().isTextual() ? RunMetric.fromKey(mn.json().asText()) : null;
                if (m == null) {
                    throw bad(mn.path(), "expected one of " + String.join(", ", keys), mn.json());
                }
                if (!seen.add(m)) {
                    throw bad(mn.path(), "metric scored twice", mn.json());
                }
                if (m == RunMetric.DRIFT_TRANS_PCT && SettingsResolver.evaluationOptions(metrics, DataKind.SPATIAL).drift() == null) {
                    throw bad(mn.path(), "drift_trans_pct needs metrics.drift settings", mn.json());
                }
                Node cn = required(t, "cap");
                double cap = number(cn, "a cap c_j > 0 (" + m.unit() + ")");
                if (!(cap > 0.0)) {
                    throw bad(cn.path(), "expected a cap c_j > 0 (" + m.unit() + ")", cn.json());
                }
                Node wn = required(t, "weight");
                double w = number(wn, "a weight w_j >= 0");
                if (w < 0.0) {
                    throw bad(wn.path(), "expected a weight w_j >= 0", wn.json());
                }
                sum += w;
                terms.add(new NormalisedScore.Term(m, cap, w));
            }
            if (Math.abs(sum - 1.0) > NormalisedScore.WEIGHT_SUM_TOLERANCE) {
                throw new InputException(source, 0, n.path(), InputProblem.INVALID_CONFIGURATION,
                        "'" + n.path() + "': weights must sum to 1 (Proposition 3)", Double.toString(sum));
            }
            return new NormalisedScore(terms);
        }

        Budget budget(Node n) {
            allowOnly(n, "device", "cores", "real_time_factor", "memory_cap_mib");
            Node d = required(n, "device");
            String device = text(d, "cpu or gpu");
            if (!device.equals("cpu") && !device.equals("gpu")) {
                throw bad(d.path(), "expected cpu or gpu", d.json());
            }
            Node c = optional(n, "cores");
            Integer cores = null;
            if (c != null) {
                long v = integer(c, "an integer >= 1");
                if (v < 1 || v > 1 << 20) {
                    throw bad(c.path(), "expected an integer >= 1", c.json());
                }
                cores = (int) v;
            }
            Double rtf = positive(required(n, "real_time_factor"), "a real-time factor > 0");
            Node mem = required(n, "memory_cap_mib");
            long mib = integer(mem, "an integer >= 1 (MiB)");
            if (mib < 1) {
                throw bad(mem.path(), "expected an integer >= 1 (MiB)", mem.json());
            }
            return new Budget(device, cores, rtf, mib);
        }
    }
}
