package org.trajeval.pipeline;

import java.util.Map;
import java.util.TreeMap;
import java.util.regex.Pattern;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Fleet labels of a run, from run.yaml or a Kafka run event, that the results store keeps as
 * columns ({@code site}, {@code software_version}) and free tags ({@code run_tags}), so gates and
 * trends can select by them ({@code --baseline software_version=2.3}, {@code --where site=hamburg},
 * {@code --where shift=night}).
 *
 * <pre>
 * site: hamburg
 * software_version: 2.4.1
 * tags: {shift: night, weather: rain}
 * </pre>
 *
 * @param site where the run was recorded, or {@code null}
 * @param softwareVersion version of the software under test (the estimator's), or {@code null}
 * @param tags free labels, key to value (keys 1-64 of {@code A-Z a-z 0-9 . _ -}, not a label
 *     column's name), sorted; empty when none
 */
public record RunLabels(String site, String softwareVersion, Map<String, String> tags) {
    /** Most free tags a run may carry. */
    public static final int MAX_TAGS = 32;
    /** Longest label value, in characters. */
    public static final int MAX_VALUE = 256;
    private static final Pattern KEY = Pattern.compile("[A-Za-z0-9_.-]{1,64}");
    /** Names a tag may not take: the store's label columns (a tag would shadow the column in a selection). */
    private static final java.util.Set<String> RESERVED = java.util.Set.of("robot", "robot_id", "site", "route",
            "sequence", "method", "software_version", "version", "dataset", "origin", "run_id", "seed");

    /** No labels. */
    public static final RunLabels NONE = new RunLabels(null, null, Map.of());

    /** @throws InputException naming the field when a value is too long or a tag key malformed or reserved */
    public RunLabels {
        value("site", site);
        value("software_version", softwareVersion);
        TreeMap<String, String> sorted = new TreeMap<>(tags == null ? Map.of() : tags);
        if (sorted.size() > MAX_TAGS) {
            throw new InputException(null, 0, "tags", InputProblem.INVALID_CONFIGURATION,
                    "tags may hold at most " + MAX_TAGS + " keys", Integer.toString(sorted.size()));
        }
        for (Map.Entry<String, String> t : sorted.entrySet()) {
            if (!KEY.matcher(t.getKey()).matches() || RESERVED.contains(t.getKey())) {
                throw new InputException(null, 0, "tags." + t.getKey(), InputProblem.INVALID_CONFIGURATION,
                        "a tag key must be 1-64 of A-Z a-z 0-9 . _ - and not one of "
                                + String.join(", ", new java.util.TreeSet<>(RESERVED)) + " (fields of their own)",
                        t.getKey());
            }
            value("tags." + t.getKey(), t.getValue());
        }
        tags = java.util.Collections.unmodifiableMap(sorted);
    }

    private static void value(String field, String v) {
        if (v != null && (v.isEmpty() || v.length() > MAX_VALUE)) {
            throw new InputException(null, 0, field, InputProblem.INVALID_CONFIGURATION,
                    field + " must be 1 to " + MAX_VALUE + " characters", v.length() > 40 ? v.substring(0, 40) : v);
        }
    }

    /** @return whether there is no label at all */
    public boolean isEmpty() {
        return site == null && softwareVersion == null && tags.isEmpty();
    }

    /** @return the labels as one canonical line for content hashes: {@code site=..;software_version=..;tags={..}} */
    public String canonical() {
        return "site=" + site + ";software_version=" + softwareVersion + ";tags=" + tags;
    }
}
