package org.trajeval.core.protocol;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.TreeSet;

/**
 * The lesson's split-hygiene rule (section 4): s(i) = s(j) implies split(i) = split(j). A session
 * (and a sequence id listed twice) whose members sit in more than one split leaks between splits.
 *
 * @param unit SESSION when sequences of one session are split apart, SEQUENCE when one sequence
 *     id itself appears in more than one split
 * @param id the session or sequence id
 * @param members per split, the sequences of this session in that split (sorted)
 */
public record SplitLeakage(Unit unit, String id, Map<Split, List<String>> members) {

    /** What leaks. */
    public enum Unit {
        /** Sequences of one session in different splits. */
        SESSION,
        /** One sequence id listed in different splits. */
        SEQUENCE
    }

    /** Copies the members. */
    public SplitLeakage {
        members = java.util.Collections.unmodifiableMap(new TreeMap<>(members));
    }

    /** @return one line for a person, e.g. "session s02: train {seq03}, test {seq04}" */
    public String describe() {
        StringBuilder sb = new StringBuilder(unit == Unit.SESSION ? "session " : "sequence ").append(id).append(':');
        String sep = " ";
        for (Map.Entry<Split, List<String>> e : members.entrySet()) {
            sb.append(sep).append(e.getKey().key()).append(" {").append(String.join(", ", e.getValue())).append('}');
            sep = ", ";
        }
        return sb.toString();
    }

    /**
     * Finds every violation, sessions first, each sorted by id.
     *
     * @param rows the split table
     * @return the violations; empty when the split is clean
     */
    public static List<SplitLeakage> find(List<SplitAssignment> rows) {
        List<SplitLeakage> out = new ArrayList<>();
        out.addAll(group(rows, Unit.SESSION));
        out.addAll(group(rows, Unit.SEQUENCE));
        return out;
    }

    private static List<SplitLeakage> group(List<SplitAssignment> rows, Unit unit) {
        Map<String, Map<Split, TreeSet<String>>> by = new TreeMap<>();
        for (SplitAssignment r : rows) {
            String key = unit == Unit.SESSION ? r.sessionId() : r.sequenceId();
            by.computeIfAbsent(key, k -> new TreeMap<>()).computeIfAbsent(r.split(), k -> new TreeSet<>())
                    .add(r.sequenceId());
        }
        List<SplitLeakage> out = new ArrayList<>();
        for (Map.Entry<String, Map<Split, TreeSet<String>>> e : by.entrySet()) {
            if (e.getValue().size() > 1) {
                Map<Split, List<String>> members = new TreeMap<>();
                e.getValue().forEach((k, v) -> members.put(k, List.copyOf(v)));
                out.add(new SplitLeakage(unit, e.getKey(), members));
            }
        }
        return out;
    }

    /** @return the split table of a manifest */
    public static List<SplitAssignment> assignments(SuiteManifest m) {
        List<SplitAssignment> rows = new ArrayList<>();
        for (SequenceSpec s : m.sequences()) {
            rows.add(new SplitAssignment(s.id(), s.session(), s.split()));
        }
        return rows;
    }
}
