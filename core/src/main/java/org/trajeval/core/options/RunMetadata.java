package org.trajeval.core.options;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.SortedMap;
import java.util.TreeMap;
import java.util.regex.Pattern;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * What a run's data is ({@link RunField}): domain, simulator, scenario, controlled factor levels and
 * the taxonomy fields. Every field is optional ({@code null}, or no factors).
 *
 * @param domain {@code sim} or {@code real}, or null
 * @param simulator the simulator's name (only with domain sim), or null
 * @param scenario the scenario id, or null
 * @param factors factor name to level (a finite number in the factor's own unit), sorted by name
 * @param environment environment word, or null
 * @param modality modality words joined with '+', or null
 * @param groundTruth ground-truth source, or null
 */
public record RunMetadata(String domain, String simulator, String scenario, SortedMap<String, Double> factors,
        String environment, String modality, String groundTruth) {
    /** No description at all. */
    public static final RunMetadata NONE = new RunMetadata(null, null, null, new TreeMap<>(), null, null, null);

    /** Most factors one sequence may declare. */
    public static final int MAX_FACTORS = 64;

    private static final Pattern WORD = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]{0,63}");
    private static final Pattern FACTOR = Pattern.compile("[a-z][a-z0-9_]{0,63}");
    private static final List<String> DOMAINS = List.of("sim", "real");
    private static final List<String> GROUND_TRUTHS = List.of("mocap", "laser_tracker", "rtk_ins", "map_alignment",
            "simulator");

    /** Copies the factors, unmodifiable. */
    public RunMetadata {
        factors = Collections.unmodifiableSortedMap(new TreeMap<>(factors == null ? Map.of() : factors));
    }

    /** @return true for a sequence of the simulation domain */
    public boolean sim() {
        return "sim".equals(domain);
    }

    /** @return true for a sequence of the real domain */
    public boolean real() {
        return "real".equals(domain);
    }

    /**
     * @param dimension a slice dimension: domain, environment, modality or ground_truth
     * @return this run's value of it, or null
     */
    public String slice(String dimension) {
        return switch (dimension) {
            case "domain" -> domain;
            case "environment" -> environment;
            case "modality" -> modality;
            case "ground_truth" -> groundTruth;
            default -> throw new IllegalArgumentException("not a slice dimension: " + dimension);
        };
    }

    /** The dimensions the report is sliced by. */
    public static final List<String> SLICE_DIMENSIONS = List.of("domain", "environment", "modality", "ground_truth");

    /** @return the factors as {@code name=level;name=level} (empty without factors) */
    public String factorsText() {
        List<String> out = new ArrayList<>();
        factors.forEach((k, v) -> out.add(k + "=" + v));
        return String.join(";", out);
    }

    /**
     * Checks the description fields found in a mapping (a manifest sequence, a run.yaml, an event).
     * Keys that are not {@link RunField}s are ignored here (the caller refuses unknown keys).
     *
     * @param tree the mapping (values: String, Number, Boolean, List, Map or null)
     * @param path key path of the mapping in its file ({@code sequences[2]}), "" at the top
     * @param source the file or event, for refusals
     * @throws InputException (INVALID_CONFIGURATION) naming the field, what was expected and what was found
     */
    public static RunMetadata parse(Map<String, ?> tree, String path, String source) {
        String domain = choice(tree, RunField.DOMAIN, DOMAINS, path, source);
        String simulator = word(tree, RunField.SIMULATOR, path, source);
        if (simulator != null && !"sim".equals(domain)) {
            throw bad(source, where(path, RunField.SIMULATOR), "applies to domain sim only (set domain: sim)",
                    simulator);
        }
        String scenario = word(tree, RunField.SCENARIO, path, source);
        SortedMap<String, Double> factors = factors(tree.get(RunField.FACTORS.key()), where(path, RunField.FACTORS),
                source);
        String environment = word(tree, RunField.ENVIRONMENT, path, source);
        String modality = modality(tree.get(RunField.MODALITY.key()), where(path, RunField.MODALITY), source);
        String groundTruth = choice(tree, RunField.GROUND_TRUTH, GROUND_TRUTHS, path, source);
        return new RunMetadata(domain, simulator, scenario, factors, environment, modality, groundTruth);
    }

    private static String where(String path, RunField f) {
        return path.isEmpty() ? f.key() : path + "." + f.key();
    }

    private static InputException bad(String source, String where, String expected, Object found) {
        return new InputException(source, 0, where, InputProblem.INVALID_CONFIGURATION, "'" + where + "': "
                + expected, found == null ? null : found instanceof Map ? "a mapping" : found instanceof List
                        ? "a list" : String.valueOf(found));
    }

    private static String choice(Map<String, ?> tree, RunField f, List<String> allowed, String path, String source) {
        Object v = tree.get(f.key());
        if (v == null) {
            return null;
        }
        String w = v instanceof String s ? s.trim().toLowerCase(Locale.ROOT) : null;
        if (w == null || !allowed.contains(w)) {
            throw bad(source, where(path, f), "expected one of " + String.join(", ", allowed), v);
        }
        return w;
    }

    private static String word(Map<String, ?> tree, RunField f, String path, String source) {
        Object v = tree.get(f.key());
        if (v == null) {
            return null;
        }
        String w = v instanceof String || v instanceof Number ? String.valueOf(v).trim() : null;
        if (w == null || !WORD.matcher(w).matches()) {
            throw bad(source, where(path, f), "expected " + f.allowed().toLowerCase(Locale.ROOT)
                    + ": a word of letters, digits, '.', '_', '-' (at most 64)", v);
        }
        return w;
    }

    private static String modality(Object v, String where, String source) {
        if (v == null) {
            return null;
        }
        List<?> items = v instanceof List<?> l ? l : List.of(v);
        if (items.isEmpty()) {
            throw bad(source, where, "expected a modality word or a non-empty list of them", v);
        }
        List<String> out = new ArrayList<>();
        for (Object item : items) {
            String w = item instanceof String s ? s.trim().toLowerCase(Locale.ROOT) : null;
            if (w == null || !WORD.matcher(w).matches()) {
                throw bad(source, where, "expected a modality word (wheel, imu, lidar, rgbd, stereo, gnss, ...)", item);
            }
            if (out.contains(w)) {
                throw bad(source, where, "modality listed twice", w);
            }
            out.add(w);
        }
        return String.join("+", out);
    }

    private static SortedMap<String, Double> factors(Object v, String where, String source) {
        SortedMap<String, Double> out = new TreeMap<>();
        if (v == null) {
            return out;
        }
        if (!(v instanceof Map<?, ?> m)) {
            throw bad(source, where, "expected a mapping of factor levels {NAME: NUMBER, ...}", v);
        }
        if (m.size() > MAX_FACTORS) {
            throw bad(source, where, "expected at most " + MAX_FACTORS + " factors", m.size());
        }
        for (Map.Entry<?, ?> e : m.entrySet()) {
            String name = String.valueOf(e.getKey());
            String at = where + "." + name;
            if (!FACTOR.matcher(name).matches()) {
                throw bad(source, at, "expected a factor name of lower-case letters, digits and '_' "
                        + "(obstacle_density)", name);
            }
            Object level = e.getValue();
            if (!(level instanceof Number n) || !Double.isFinite(n.doubleValue())) {
                throw bad(source, at, "expected the factor's level, a finite number", level);
            }
            out.put(name, n.doubleValue());
        }
        return out;
    }
}
