package org.trajeval.store;

import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;
import org.trajeval.core.protocol.RegressionGate;
import org.trajeval.core.protocol.RegressionGate.Finding;
import org.trajeval.core.report.SuiteReport.Paired;

/**
 * The regression gate between two selections of stored runs, paired and averaged in SQL: per side
 * one grouped query per (method, sequence, seed), joined on the keys both sides have and summed per
 * (method, sequence), so only per-sequence sums leave the database (at 10^5 runs a side: a few
 * hundred rows instead of 2 x 10^5). The statistics are then {@link RegressionGate#gateAllPaired},
 * the rule of the file gate.
 *
 * <p>Per (method, sequence) and metric, a side's value is the mean over its runs whose (sequence,
 * seed) the other side also has ({@link GatePairing}), counting successful runs with the metric
 * (the score: every run that has one). This is what {@link RegressionGate#gate} computes from the
 * same runs as suite run entries; {@code StoredGateTest} checks the two agree on both databases.
 */
public final class StoredGate {
    private StoredGate() {
    }

    /**
     * What the gate found, and what it paired.
     *
     * @param findings one per (method, metric), methods then metrics in order
     * @param methods the candidate's methods that the baseline has, sorted
     * @param baselineMethods every method of the baseline runs, sorted
     * @param baselineSequences pairing sequences of the baseline runs
     * @param baselineRuns baseline runs selected
     * @param candidateRuns candidate runs selected
     */
    public record Result(List<Finding> findings, List<String> methods, List<String> baselineMethods,
            int baselineSequences, long baselineRuns, long candidateRuns) {
    }

    /**
     * @param tolerances metric column to allowed relative worsening (0.05 = 5 %), in output order
     * @throws StoreException BAD_QUERY when a selection takes no run, or the sides share no method
     */
    public static Result gate(ResultsStore store, Selection baseline, Selection candidate, GatePairing pairing,
            Map<String, Double> tolerances, RegressionGate.Settings settings) {
        tolerances.keySet().forEach(StoredMetric::require);
        List<SideCell> b = sideCells(store, baseline, pairing);
        List<SideCell> c = sideCells(store, candidate, pairing);
        if (b.isEmpty() || c.isEmpty()) {
            throw new StoreException(StoreException.Problem.BAD_QUERY, "gate: no stored run matches "
                    + (b.isEmpty() ? "--baseline " + baseline : "--candidate " + candidate), null);
        }
        TreeSet<String> baseMethods = new TreeSet<>();
        TreeSet<String> sequences = new TreeSet<>();
        b.forEach(x -> {
            baseMethods.add(x.method());
            sequences.add(x.sequence());
        });
        TreeSet<String> methods = new TreeSet<>();
        c.stream().map(SideCell::method).filter(baseMethods::contains).forEach(methods::add);
        if (methods.isEmpty()) {
            throw new StoreException(StoreException.Problem.BAD_QUERY, "gate: the candidate runs have no method of "
                    + "the baseline runs " + baseMethods, null);
        }
        List<PairedCell> cells = pairedCells(store, baseline, candidate, pairing, List.copyOf(tolerances.keySet()));
        List<Finding> findings = findings(cells, List.copyOf(methods), tolerances, settings);
        return new Result(findings, List.copyOf(methods), List.copyOf(baseMethods), sequences.size(),
                b.stream().mapToLong(SideCell::runs).sum(), c.stream().mapToLong(SideCell::runs).sum());
    }

    /**
     * The gate's statistics on aggregated cells: per (method, metric) the paired sequences in
     * sorted order (the order the bootstrap resamples by), a = candidate mean, b = baseline mean.
     */
    public static List<Finding> findings(List<PairedCell> cells, List<String> methods,
            Map<String, Double> tolerances, RegressionGate.Settings settings) {
        Map<String, List<Paired>> pairs = new HashMap<>();
        cells.stream().filter(PairedCell::paired).sorted(Comparator.comparing(PairedCell::sequence))
                .forEach(x -> pairs.computeIfAbsent(x.method() + "\u0000" + x.metric(), k -> new ArrayList<>())
                        .add(new Paired(x.sequence(), x.candidateMean(), x.baselineMean(),
                                x.candidateMean() - x.baselineMean())));
        return RegressionGate.gateAllPaired(methods, tolerances,
                (m, metric) -> pairs.getOrDefault(m + "\u0000" + metric, List.of()), settings);
    }

    /** @return per (method, sequence) how many runs the selection takes: one grouped query */
    static List<SideCell> sideCells(ResultsStore store, Selection side, GatePairing pairing) {
        List<Object> args = new ArrayList<>();
        String sql = sideSql(side, pairing, args);
        return store.read("select " + side, c -> {
            try (PreparedStatement s = c.prepareStatement(sql)) {
                ResultsStore.bindAll(s, args);
                List<SideCell> out = new ArrayList<>();
                try (ResultSet rs = s.executeQuery()) {
                    while (rs.next()) {
                        out.add(new SideCell(rs.getString(1), rs.getString(2), rs.getLong(3)));
                    }
                }
                return out;
            }
        });
    }

    /** @return the SQL of {@link #sideCells}; its values are appended to {@code args} */
    static String sideSql(Selection side, GatePairing pairing, List<Object> args) {
        String method = GatePairing.methodExpression();
        String seq = pairing.sequenceExpression();
        StringBuilder sql = new StringBuilder("SELECT ").append(method).append(", ").append(seq)
                .append(", COUNT(*) FROM runs r WHERE 1 = 1");
        side.appendWhere(sql, args);
        sql.append(" GROUP BY ").append(method).append(", ").append(seq);
        return sql.toString();
    }

    /**
     * One query: each side grouped by (method, sequence, seed) with a count and a sum per metric,
     * the two joined on those keys, summed per (method, sequence).
     *
     * @return one cell per (method, paired sequence, metric)
     */
    static List<PairedCell> pairedCells(ResultsStore store, Selection baseline, Selection candidate,
            GatePairing pairing, List<String> metrics) {
        List<Object> args = new ArrayList<>();
        String sql = pairedSql(baseline, candidate, pairing, metrics, args);
        return store.read("pair " + baseline + " with " + candidate, c -> {
            try (PreparedStatement s = c.prepareStatement(sql)) {
                ResultsStore.bindAll(s, args);
                List<PairedCell> out = new ArrayList<>();
                try (ResultSet rs = s.executeQuery()) {
                    while (rs.next()) {
                        for (int i = 0; i < metrics.size(); i++) {
                            int col = 3 + 4 * i;
                            out.add(new PairedCell(rs.getString(1), rs.getString(2), metrics.get(i),
                                    rs.getLong(col), rs.getDouble(col + 1), rs.getLong(col + 2),
                                    rs.getDouble(col + 3)));
                        }
                    }
                }
                return out;
            }
        });
    }

    /** @return the SQL of {@link #pairedCells}; its values are appended to {@code args} */
    static String pairedSql(Selection baseline, Selection candidate, GatePairing pairing, List<String> metrics,
            List<Object> args) {
        StringBuilder sql = new StringBuilder("SELECT b.method, b.seq");
        for (int i = 0; i < metrics.size(); i++) {
            sql.append(", SUM(b.n").append(i).append("), SUM(b.s").append(i).append("), SUM(c.n").append(i)
                    .append("), SUM(c.s").append(i).append(")");
        }
        sql.append(" FROM ");
        side(sql, args, baseline, pairing, metrics);
        sql.append(" b JOIN ");
        side(sql, args, candidate, pairing, metrics);
        sql.append(" c ON c.method = b.method AND c.seq = b.seq AND c.seed = b.seed GROUP BY b.method, b.seq");
        return sql.toString();
    }

    /**
     * Appends one side's grouped subquery: (method, seq, seed, n0, s0, n1, s1, ...). The inner query
     * groups by the raw key columns (in the order of the version index, which then holds every
     * column it reads: no sort, no table access); the outer one merges groups whose keys coincide
     * once NULLs read as {@code -} or 0.
     */
    private static void side(StringBuilder sql, List<Object> args, Selection selection, GatePairing pairing,
            List<String> metrics) {
        sql.append("(SELECT method, seq, seed");
        for (int i = 0; i < metrics.size(); i++) {
            sql.append(", SUM(n").append(i).append(") AS n").append(i).append(", SUM(s").append(i).append(") AS s")
                    .append(i);
        }
        sql.append(" FROM (SELECT ").append(GatePairing.methodExpression()).append(" AS method, ")
                .append(pairing.sequenceExpression()).append(" AS seq, ").append(pairing.seedExpression())
                .append(" AS seed");
        for (int i = 0; i < metrics.size(); i++) {
            String v = value(metrics.get(i));
            sql.append(", COUNT(").append(v).append(") AS n").append(i).append(", SUM(").append(v).append(") AS s")
                    .append(i);
        }
        sql.append(" FROM runs r WHERE 1 = 1");
        selection.appendWhere(sql, args);
        sql.append(" GROUP BY ").append(pairing.keyColumns()).append(") k GROUP BY method, seq, seed)");
    }

    /** @return the SQL of a metric's value: successful runs only, except the score (a failed run scores 0) */
    private static String value(String metric) {
        String column = "r." + StoredMetric.require(metric);
        return StoredMetric.SCORE.equals(metric) ? column : "CASE WHEN r.status = 'ok' THEN " + column + " END";
    }
}
