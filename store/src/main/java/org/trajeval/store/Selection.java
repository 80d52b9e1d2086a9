package org.trajeval.store;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Pattern;

/**
 * Which stored runs a query takes: {@code KEY=VALUE[,KEY=VALUE...]}, every condition required.
 * A key is a label column ({@code robot site route method software_version} (alias
 * {@code version}), {@code dataset origin run_id seed}) or else a free tag of {@code run_tags}.
 * Example: {@code software_version=2.4,site=hamburg}.
 *
 * @param conditions key to required value, in the order given
 */
public record Selection(Map<String, String> conditions) {
    /** The label columns a selection or a trend slice may name. */
    public static final List<String> COLUMNS = List.of("robot", "site", "route", "method", "software_version",
            "dataset", "origin", "run_id", "seed");
    private static final Pattern KEY = Pattern.compile("[A-Za-z0-9_.-]{1,64}");

    /** @throws IllegalArgumentException on a malformed key */
    public Selection {
        conditions = java.util.Collections.unmodifiableMap(new LinkedHashMap<>(conditions));
        for (String k : conditions.keySet()) {
            if (!KEY.matcher(k).matches()) {
                throw new IllegalArgumentException("selection key must be 1-64 of A-Z a-z 0-9 . _ -, found " + k);
            }
        }
    }

    /** Every run. */
    public static Selection all() {
        return new Selection(Map.of());
    }

    /**
     * @param text {@code KEY=VALUE[,KEY=VALUE...]}
     * @param option the option it came from, for the message
     * @throws StoreException BAD_QUERY on a malformed condition
     */
    public static Selection parse(String text, String option) {
        Map<String, String> c = new LinkedHashMap<>();
        for (String part : text.split(",")) {
            int eq = part.indexOf('=');
            String key = eq < 0 ? "" : part.substring(0, eq).strip();
            if (eq < 0 || !KEY.matcher(key).matches()) {
                throw new StoreException(StoreException.Problem.BAD_QUERY, option
                        + ": expected KEY=VALUE[,KEY=VALUE...] (e.g. software_version=2.4), found \"" + text + "\"",
                        null);
            }
            c.put(column(key), part.substring(eq + 1).strip());
        }
        return new Selection(c);
    }

    /** @return the column a key names ({@code version} is {@code software_version}), or the key itself */
    static String column(String key) {
        return "version".equals(key) ? "software_version" : key;
    }

    /** Appends {@code AND ...} conditions on table alias {@code r} to {@code sql} and their values to {@code args}. */
    void appendWhere(StringBuilder sql, List<Object> args) {
        for (Map.Entry<String, String> e : conditions.entrySet()) {
            if ("seed".equals(e.getKey())) {
                sql.append(" AND r.seed = ?");
                args.add(parseSeed(e.getValue()));
            } else if (COLUMNS.contains(e.getKey())) {
                sql.append(" AND r.").append(e.getKey()).append(" = ?");
                args.add(e.getValue());
            } else {
                sql.append(" AND EXISTS (SELECT 1 FROM run_tags t WHERE t.result_sha256 = r.result_sha256"
                        + " AND t.tag = ? AND t.value = ?)");
                args.add(e.getKey());
                args.add(e.getValue());
            }
        }
    }

    static long parseSeed(String v) {
        try {
            return Long.parseLong(v);
        } catch (NumberFormatException e) {
            throw new StoreException(StoreException.Problem.BAD_QUERY, "seed: expected an integer, found \"" + v + "\"",
                    e);
        }
    }

    /** @return the text form {@code KEY=VALUE,...} */
    @Override
    public String toString() {
        List<String> parts = new ArrayList<>();
        conditions.forEach((k, v) -> parts.add(k + "=" + v));
        return String.join(",", parts);
    }
}
