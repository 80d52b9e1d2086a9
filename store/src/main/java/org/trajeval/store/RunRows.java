package org.trajeval.store;

import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Types;
import java.time.Instant;
import java.util.HashMap;
import java.util.Map;

/**
 * A stored run as a row of the {@code runs} table, written once for both directions: the
 * columns in order, a {@link RunRecord} bound to the parameters of {@link #INSERT} (labels,
 * description, metrics; a non-finite metric is stored as NULL) and read back from a
 * {@code SELECT} of {@link #COLUMNS} (labels and metrics; tags are read apart, from
 * {@code run_tags}).
 */
final class RunRows {
    /** The label columns, in the order {@link #bind} and {@link #read} use. */
    static final String LABELS = "result_sha256, origin, run_id, run_version, content_sha256, dataset, robot, site, "
            + "route, method, software_version, seed, recorded_at, recorded_ms, status, failure_reason, source";
    private static final int LABEL_COUNT = 17;

    /** Inserts one run, leaving a run with the same key as it is. */
    static final String INSERT = "INSERT INTO runs (" + LABELS + ", " + RunDescription.COLUMNS
            + metricColumns() + ") VALUES (?"
            + ", ?".repeat(LABEL_COUNT - 1 + RunDescription.COUNT + StoredMetric.keys().size())
            + ") ON CONFLICT (result_sha256) DO NOTHING";

    /** What {@link #read} reads, from {@code runs r}: the labels, then the metrics. */
    static final String COLUMNS = LABELS.replace("result_sha256", "r.result_sha256") + metricColumns();

    private RunRows() {
    }

    private static String metricColumns() {
        StringBuilder sql = new StringBuilder();
        for (String m : StoredMetric.keys()) {
            sql.append(", ").append(m);
        }
        return sql.toString();
    }

    /** Binds a run to the parameters of {@link #INSERT}. */
    static void bind(PreparedStatement s, RunRecord r) throws SQLException {
        int i = 1;
        s.setString(i++, r.resultSha256());
        s.setString(i++, r.origin());
        s.setString(i++, r.runId());
        setInt(s, i++, r.runVersion());
        s.setString(i++, r.contentSha256());
        s.setString(i++, r.dataset());
        s.setString(i++, r.robot());
        s.setString(i++, r.site());
        s.setString(i++, r.route());
        s.setString(i++, r.method());
        s.setString(i++, r.softwareVersion());
        setLong(s, i++, r.seed());
        s.setString(i++, r.recordedAt().toString());
        s.setLong(i++, r.recordedAt().toEpochMilli());
        s.setString(i++, r.ok() ? "ok" : "failed");
        s.setString(i++, r.failureReason());
        s.setString(i++, r.source());
        Object[] description = r.description().values();
        for (int k = 0; k < description.length; k++) {
            boolean number = k >= RunDescription.COUNT - 2; // wall_time_s, peak_memory_mib
            if (description[k] == null) {
                s.setNull(i++, number ? Types.DOUBLE : Types.VARCHAR);
            } else if (number) {
                s.setDouble(i++, (Double) description[k]);
            } else {
                s.setString(i++, (String) description[k]);
            }
        }
        for (String m : StoredMetric.keys()) {
            Double v = r.metrics().get(m);
            if (v == null || !Double.isFinite(v)) {
                s.setNull(i++, Types.DOUBLE);
            } else {
                s.setDouble(i++, v);
            }
        }
    }

    /** @return the run at the result set's row, a {@code SELECT} of {@link #COLUMNS}, without tags */
    static RunRecord read(ResultSet rs) throws SQLException {
        Map<String, Double> metrics = new HashMap<>();
        int col = LABEL_COUNT + 1;
        for (String m : StoredMetric.keys()) {
            double v = rs.getDouble(col++);
            if (!rs.wasNull()) {
                metrics.put(m, v);
            }
        }
        int version = rs.getInt(4);
        Integer runVersion = rs.wasNull() ? null : version;
        long seed = rs.getLong(12);
        Long seedValue = rs.wasNull() ? null : seed;
        return new RunRecord(rs.getString(1), rs.getString(2), rs.getString(3), runVersion, rs.getString(5),
                rs.getString(6), rs.getString(7), rs.getString(8), rs.getString(9), rs.getString(10),
                rs.getString(11), seedValue, Instant.ofEpochMilli(rs.getLong(14)), "ok".equals(rs.getString(15)),
                rs.getString(16), metrics, rs.getString(17), Map.of());
    }

    private static void setInt(PreparedStatement s, int i, Integer v) throws SQLException {
        if (v == null) {
            s.setNull(i, Types.INTEGER);
        } else {
            s.setInt(i, v);
        }
    }

    private static void setLong(PreparedStatement s, int i, Long v) throws SQLException {
        if (v == null) {
            s.setNull(i, Types.BIGINT);
        } else {
            s.setLong(i, v);
        }
    }
}
