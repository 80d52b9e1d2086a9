package org.trajeval.store;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Labels given when results are recorded ({@code --tag KEY=VALUE}): {@code software_version}
 * (alias {@code version}), {@code robot}, {@code site} and {@code route} fill their columns (where
 * the report has no value of its own); every other key becomes a free tag.
 *
 * @param columns label column to value
 * @param tags free tag to value
 */
public record Labels(Map<String, String> columns, Map<String, String> tags) {
    /** The label columns of a recording whose reports name method and seed themselves (suite, pipeline). */
    public static final List<String> LABEL_COLUMNS = List.of("software_version", "robot", "site", "route");
    /** The label columns of one evaluation ({@code eval --db}), which has no method or seed of its own. */
    public static final List<String> EVAL_COLUMNS = List.of("software_version", "robot", "site", "route", "method",
            "seed");

    /** Compact constructor: copies, sorted. */
    public Labels {
        columns = Map.copyOf(new TreeMap<>(columns));
        tags = Map.copyOf(new TreeMap<>(tags));
    }

    /** No labels. */
    public static Labels none() {
        return new Labels(Map.of(), Map.of());
    }

    /**
     * @param pairs {@code KEY=VALUE} texts
     * @throws StoreException BAD_QUERY on a malformed pair
     */
    public static Labels parse(List<String> pairs) {
        return parse(pairs, LABEL_COLUMNS);
    }

    /**
     * @param pairs {@code KEY=VALUE} texts
     * @param columns the label columns a tag may fill ({@link #LABEL_COLUMNS} or {@link #EVAL_COLUMNS})
     * @throws StoreException BAD_QUERY on a malformed pair, a column the report fills itself, or a
     *     seed that is no whole number
     */
    public static Labels parse(List<String> pairs, List<String> columns) {
        Map<String, String> cols = new LinkedHashMap<>();
        Map<String, String> tags = new LinkedHashMap<>();
        for (String p : pairs) {
            Selection one = Selection.parse(p, "--tag");
            one.conditions().forEach((k, v) -> {
                if (columns.contains(k)) {
                    if ("seed".equals(k)) {
                        Selection.parseSeed(v);
                    }
                    cols.put(k, v);
                } else if (Selection.COLUMNS.contains(k)) {
                    throw new StoreException(StoreException.Problem.BAD_QUERY, "--tag: '" + k + "' comes from the "
                            + "report itself; a tag may set " + String.join(", ", columns) + " or a free key", null);
                } else {
                    tags.put(k, v);
                }
            });
        }
        return new Labels(cols, tags);
    }

    /** @return the column's label, or {@code fallback} when not given */
    public String column(String name, String fallback) {
        return fallback != null ? fallback : columns.get(name);
    }

    /**
     * @return a canonical text of every label, for result keys: keys sorted, e.g.
     *     {@code {site=hamburg, software_version=2.4}|{shift=night}} (sorted explicitly: the iteration
     *     order of {@code Map.copyOf} changes from one JVM to the next, and a key must not)
     */
    String canonical() {
        return new TreeMap<>(columns) + "|" + new TreeMap<>(tags);
    }
}
