package org.trajeval.store;

import java.sql.Connection;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.TreeMap;

/**
 * The trend aggregates of schema v4 ({@code trend_cells}): per metric, slice column, slice value,
 * software version and UTC day, the count, compensated sums of the values and of their squares, and
 * the first and last recording time of the successful runs. Kept up to date in the transaction that
 * inserts runs ({@link #add}), from the runs that were new, so a re-recorded result adds nothing and
 * concurrent writers each add the runs they inserted. A whole-history trend then reads these cells
 * ({@link #fromAggregates}): at 10^6 runs over 100 days, about 5 000 rows per (metric, slice) instead of 10^6.
 *
 * <p>Which trends they serve ({@link #serves}): slices by robot, site, route, method or version,
 * every run (no {@code --where}), since a UTC midnight at or after the epoch. Any other trend is
 * aggregated from {@code runs} as before.
 */
final class TrendCells {
    /** The slice columns kept. */
    static final List<String> SLICES = List.of("robot", "site", "route", "method", "software_version");
    /** One UTC day (ms). */
    static final long DAY_MS = 86_400_000L;
    private static final Comparator<String> NULLS_FIRST = Comparator.nullsFirst(Comparator.naturalOrder());
    private static final Comparator<Key> KEY_ORDER = Comparator.comparing(Key::metric).thenComparing(Key::slice)
            .thenComparingLong(Key::day).thenComparing(Key::value, NULLS_FIRST)
            .thenComparing(Key::version, NULLS_FIRST);

    private TrendCells() {
    }

    /**
     * One row's key; a null value or version is a run without that label.
     *
     * @param day UTC day number, recorded_ms / 86 400 000
     */
    record Key(String metric, String slice, long day, String value, String version) {
        Key {
            Objects.requireNonNull(metric, "metric");
            Objects.requireNonNull(slice, "slice");
        }
    }

    /**
     * A running sum with its rounding error (Neumaier's variant of Kahan summation: the error of each
     * addition is kept in {@code lo}, so {@code hi + lo} is the sum as if added exactly, in all but
     * extreme cases). Mutable, local to one computation.
     */
    static final class Sum {
        double hi;
        double lo;

        void add(double x) {
            double t = hi + x;
            lo += Math.abs(hi) >= Math.abs(x) ? (hi - t) + x : (x - t) + hi;
            hi = t;
        }

        void add(double xHi, double xLo) {
            add(xHi);
            lo += xLo;
        }

        double value() {
            return hi + lo;
        }
    }

    /** The aggregate of one key; mutable while a batch or a query is summed. */
    private static final class Cell {
        long n;
        final Sum sum = new Sum();
        final Sum squares = new Sum();
        long firstMs = Long.MAX_VALUE;
        long lastMs = Long.MIN_VALUE;

        void addRun(double v, long ms) {
            n++;
            sum.add(v);
            squares.add(v * v);
            firstMs = Math.min(firstMs, ms);
            lastMs = Math.max(lastMs, ms);
        }
    }

    /** @return whether a trend with these arguments can be read from the aggregates */
    static boolean serves(String slice, Selection selection, long sinceMs) {
        return SLICES.contains(slice) && selection.conditions().isEmpty() && sinceMs >= 0 && sinceMs % DAY_MS == 0;
    }

    /** @return the label of run {@code r} in slice column {@code slice} */
    private static String label(RunRecord r, String slice) {
        return switch (slice) {
            case "robot" -> r.robot();
            case "site" -> r.site();
            case "route" -> r.route();
            case "method" -> r.method();
            default -> r.softwareVersion();
        };
    }

    /**
     * Adds newly inserted runs to the aggregates, on the connection's open transaction. The cells
     * are written in one order (sorted by key), so concurrent writers wait for each other instead of
     * deadlocking. What is kept follows what the runs table holds: successful runs, finite values
     * (a non-finite one is stored as NULL), recorded at or after the epoch.
     */
    static void add(Connection c, List<RunRecord> inserted) throws SQLException {
        Map<Key, Cell> cells = new TreeMap<>(KEY_ORDER);
        for (RunRecord r : inserted) {
            long ms = r.recordedAt().toEpochMilli();
            if (!r.ok() || ms < 0) {
                continue;
            }
            for (Map.Entry<String, Double> m : r.metrics().entrySet()) {
                double v = m.getValue();
                if (!Double.isFinite(v)) {
                    continue;
                }
                for (String slice : SLICES) {
                    cells.computeIfAbsent(new Key(m.getKey(), slice, ms / DAY_MS, label(r, slice),
                            r.softwareVersion()), k -> new Cell()).addRun(v, ms);
                }
            }
        }
        if (cells.isEmpty()) {
            return;
        }
        // the error of adding two sums a + b: (a - ((a + b) - ((a + b) - a))) + (b - ((a + b) - a)) (Knuth's TwoSum)
        String upsert = "INSERT INTO trend_cells (metric, slice, day, slice_value, slice_missing, software_version, "
                + "version_missing, n, sum, sum_lo, sum_squares, sum_squares_lo, first_ms, last_ms) "
                + "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?) ON CONFLICT (metric, slice, day, slice_value, "
                + "slice_missing, software_version, version_missing) DO UPDATE SET n = trend_cells.n + excluded.n, "
                + "sum = trend_cells.sum + excluded.sum, sum_lo = trend_cells.sum_lo + excluded.sum_lo + "
                + twoSumError("trend_cells.sum", "excluded.sum") + ", sum_squares = trend_cells.sum_squares + "
                + "excluded.sum_squares, sum_squares_lo = trend_cells.sum_squares_lo + excluded.sum_squares_lo + "
                + twoSumError("trend_cells.sum_squares", "excluded.sum_squares") + ", first_ms = CASE WHEN "
                + "excluded.first_ms < trend_cells.first_ms THEN excluded.first_ms ELSE trend_cells.first_ms END, "
                + "last_ms = CASE WHEN excluded.last_ms > trend_cells.last_ms THEN excluded.last_ms "
                + "ELSE trend_cells.last_ms END";
        try (PreparedStatement s = c.prepareStatement(upsert)) {
            for (Map.Entry<Key, Cell> e : cells.entrySet()) {
                Key k = e.getKey();
                Cell v = e.getValue();
                int i = 1;
                s.setString(i++, k.metric());
                s.setString(i++, k.slice());
                s.setLong(i++, k.day());
                s.setString(i++, k.value() == null ? "" : k.value());
                s.setInt(i++, k.value() == null ? 1 : 0);
                s.setString(i++, k.version() == null ? "" : k.version());
                s.setInt(i++, k.version() == null ? 1 : 0);
                s.setLong(i++, v.n);
                s.setDouble(i++, v.sum.hi);
                s.setDouble(i++, v.sum.lo);
                s.setDouble(i++, v.squares.hi);
                s.setDouble(i++, v.squares.lo);
                s.setLong(i++, v.firstMs);
                s.setLong(i++, v.lastMs);
                s.addBatch();
            }
            s.executeBatch();
        }
    }

    /** @return the SQL of the rounding error of {@code a + b} (both dialects evaluate it in IEEE doubles) */
    private static String twoSumError(String a, String b) {
        String s = "(" + a + " + " + b + ")";
        String bb = "(" + s + " - " + a + ")";
        return "((" + a + " - (" + s + " - " + bb + ")) + (" + b + " - " + bb + "))";
    }

    /**
     * The trend cells of one metric and slice column from the aggregates: the day rows summed into
     * the bucket (day; week = day / 7, as {@code recorded_ms / 604 800 000}; version), in the same
     * labels as {@link #fromRuns}.
     */
    static List<TrendCell> fromAggregates(Connection c, String metric, String slice, TrendBucket bucket, long sinceMs)
            throws SQLException {
        Map<List<String>, Cell> cells = new LinkedHashMap<>();
        try (PreparedStatement s = c.prepareStatement("SELECT day, slice_value, slice_missing, software_version, "
                + "version_missing, n, sum, sum_lo, sum_squares, sum_squares_lo, first_ms, last_ms FROM trend_cells "
                + "WHERE metric = ? AND slice = ? AND day >= ? ORDER BY day, slice_value, slice_missing, "
                + "software_version, version_missing")) {
            s.setString(1, metric);
            s.setString(2, slice);
            s.setLong(3, sinceMs / DAY_MS);
            try (ResultSet rs = s.executeQuery()) {
                while (rs.next()) {
                    long day = rs.getLong(1);
                    String value = rs.getInt(3) == 1 ? null : rs.getString(2);
                    String version = rs.getInt(5) == 1 ? null : rs.getString(4);
                    String b = switch (bucket) {
                        case DAY -> Long.toString(day);
                        case WEEK -> Long.toString(day / 7);
                        case VERSION -> version;
                    };
                    Cell cell = cells.computeIfAbsent(java.util.Arrays.asList(value, b), k -> new Cell());
                    cell.n += rs.getLong(6);
                    cell.sum.add(rs.getDouble(7), rs.getDouble(8));
                    cell.squares.add(rs.getDouble(9), rs.getDouble(10));
                    cell.firstMs = Math.min(cell.firstMs, rs.getLong(11));
                    cell.lastMs = Math.max(cell.lastMs, rs.getLong(12));
                }
            }
        }
        List<TrendCell> out = new ArrayList<>(cells.size());
        cells.forEach((k, v) -> out.add(new TrendCell(k.get(0), k.get(1), v.n, v.sum.value(), v.squares.value(),
                v.firstMs, v.lastMs)));
        return out;
    }

    /**
     * The trend cells aggregated from the runs table, for any selection: one grouped query, so only
     * the cells leave the database.
     */
    static List<TrendCell> fromRuns(Connection c, String metric, String slice, TrendBucket bucket,
            Selection selection, long sinceMs) throws SQLException {
        String b = bucket.expression();
        StringBuilder sql = new StringBuilder("SELECT r.").append(slice).append(", ").append(b)
                .append(" AS bucket, COUNT(*), SUM(").append(metric).append("), SUM(").append(metric).append(" * ")
                .append(metric).append("), MIN(r.recorded_ms), MAX(r.recorded_ms) FROM runs r WHERE r.")
                .append(metric).append(" IS NOT NULL AND r.status = 'ok' AND r.recorded_ms >= ?");
        List<Object> args = new ArrayList<>();
        args.add(sinceMs);
        selection.appendWhere(sql, args);
        sql.append(" GROUP BY r.").append(slice).append(", ").append(b);
        try (PreparedStatement s = c.prepareStatement(sql.toString())) {
            ResultsStore.bindAll(s, args);
            List<TrendCell> cells = new ArrayList<>();
            try (ResultSet rs = s.executeQuery()) {
                while (rs.next()) {
                    cells.add(new TrendCell(rs.getString(1), rs.getString(2), rs.getLong(3), rs.getDouble(4),
                            rs.getDouble(5), rs.getLong(6), rs.getLong(7)));
                }
            }
            return cells;
        }
    }
}
