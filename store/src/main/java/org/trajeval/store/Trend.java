package org.trajeval.store;

import java.time.LocalDate;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.trajeval.core.stats.Holm;
import org.trajeval.core.stats.Interval;
import org.trajeval.core.stats.WelchTest;

/**
 * A metric's history per slice (robot, site, route, method or version), with a t-interval per
 * bucket and a flag on slices whose latest bucket is worse than their history.
 *
 * <p>Rule: per slice, the latest bucket (by first recording time) against all earlier buckets
 * pooled; Welch's one-sided t-test in the worse direction (higher for error metrics, lower for the
 * score and the coverage); the p-values of the slices that have at least 2 values on both sides
 * are Holm-adjusted together ({@link Holm}) (family-wise error rate alpha = 1 - confidence across slices), and a
 * slice is flagged when its adjusted p is below alpha. Pooled variances come from the cells' sums
 * of squares (fine for metric values of similar magnitude, which these are).
 */
public final class Trend {
    private Trend() {
    }

    /**
     * One bucket of one slice.
     *
     * @param bucket the bucket's label (a date for day and week buckets, the version otherwise)
     * @param n runs in it
     * @param mean mean of the metric (metric unit)
     * @param interval t-interval of the mean at the trend's confidence, null when n &lt; 2
     * @param firstMs earliest recording time (ms since the epoch)
     */
    public record Point(String bucket, long n, double mean, Interval interval, long firstMs) {
    }

    /**
     * One slice's history and finding.
     *
     * @param slice the slice's label ("-" for runs without one)
     * @param points buckets in time order
     * @param historyN runs before the latest bucket
     * @param historyMean their mean, NaN when none
     * @param pValue Welch one-sided p of "latest worse than history", NaN when not testable
     * @param adjustedP Holm-adjusted p across the tested slices, NaN when not tested
     * @param flagged whether the latest bucket is worse than the history at the family-wise level
     */
    public record Slice(String slice, List<Point> points, long historyN, double historyMean, double pValue,
            double adjustedP, boolean flagged) {
        /** @return the latest bucket */
        public Point latest() {
            return points.get(points.size() - 1);
        }
    }

    /**
     * @param metric the metric column
     * @param by the slicing column
     * @param bucket the bucketing
     * @param confidence the intervals' level and 1 - alpha of the flags
     * @param slices every slice, by label
     */
    public record Result(String metric, String by, TrendBucket bucket, double confidence, List<Slice> slices) {
    }

    /** Queries the store and analyses the cells. */
    public static Result of(ResultsStore store, String metric, String by, TrendBucket bucket, Selection where,
            long sinceMs, double confidence) {
        String column = Selection.column(by);
        return analyse(store.trendCells(metric, column, bucket, where, sinceMs), metric, column, bucket, confidence);
    }

    /** Analyses aggregated cells (see the class comment for the rule). */
    public static Result analyse(List<TrendCell> cells, String metric, String by, TrendBucket bucket,
            double confidence) {
        if (!(confidence > 0 && confidence < 1)) {
            throw new StoreException(StoreException.Problem.BAD_QUERY, "--confidence must be in (0, 1), found "
                    + confidence, null);
        }
        boolean higherBetter = StoredMetric.higherIsBetter(metric);
        Map<String, List<TrendCell>> bySlice = new LinkedHashMap<>();
        // ties in the first recording time are broken by the labels, so the order is the same whichever
        // way the cells were aggregated (from the runs or from trend_cells)
        Comparator<String> nullsFirst = Comparator.nullsFirst(Comparator.naturalOrder());
        cells.stream().sorted(Comparator.comparing((TrendCell c) -> c.slice() == null ? "-" : c.slice())
                .thenComparingLong(TrendCell::firstMs).thenComparing(TrendCell::bucket, nullsFirst)
                .thenComparing(TrendCell::slice, nullsFirst))
                .forEach(c -> bySlice.computeIfAbsent(c.slice() == null ? "-" : c.slice(), k -> new ArrayList<>())
                        .add(c));
        List<String> names = new ArrayList<>(bySlice.keySet());
        double[] p = new double[names.size()];
        List<List<Point>> points = new ArrayList<>();
        long[] histN = new long[names.size()];
        double[] histMean = new double[names.size()];
        for (int i = 0; i < names.size(); i++) {
            List<TrendCell> cs = bySlice.get(names.get(i));
            List<Point> pts = new ArrayList<>();
            for (TrendCell c : cs) {
                Interval iv = c.n() >= 2 ? WelchTest.meanInterval(c.n(), c.mean(), Math.sqrt(c.variance()),
                        confidence) : null;
                pts.add(new Point(label(c.bucket(), bucket), c.n(), c.mean(), iv, c.firstMs()));
            }
            points.add(pts);
            TrendCell latest = cs.get(cs.size() - 1);
            long n = 0;
            double sum = 0;
            double sq = 0;
            for (TrendCell c : cs.subList(0, cs.size() - 1)) {
                n += c.n();
                sum += c.sum();
                sq += c.sumSquares();
            }
            histN[i] = n;
            histMean[i] = n == 0 ? Double.NaN : sum / n;
            p[i] = Double.NaN;
            if (n >= 2 && latest.n() >= 2) {
                TrendCell hist = new TrendCell(names.get(i), "history", n, sum, sq, 0, 0);
                p[i] = higherBetter
                        ? WelchTest.greater(hist.n(), hist.mean(), hist.variance(), latest.n(), latest.mean(),
                                latest.variance())
                        : WelchTest.greater(latest.n(), latest.mean(), latest.variance(), hist.n(), hist.mean(),
                                hist.variance());
            }
        }
        double[] adj = holmOverTested(p);
        double alpha = 1 - confidence;
        List<Slice> slices = new ArrayList<>();
        for (int i = 0; i < names.size(); i++) {
            slices.add(new Slice(names.get(i), points.get(i), histN[i], histMean[i], p[i], adj[i], adj[i] < alpha));
        }
        return new Result(metric, by, bucket, confidence, slices);
    }

    /**
     * Holm's adjustment ({@link Holm#adjust}) over the slices that were tested: the finite p-values
     * form the family, an untested slice (NaN) stays NaN and does not count in m.
     */
    static double[] holmOverTested(double[] p) {
        int[] tested = java.util.stream.IntStream.range(0, p.length).filter(i -> !Double.isNaN(p[i])).toArray();
        double[] family = new double[tested.length];
        for (int j = 0; j < tested.length; j++) {
            family[j] = p[tested[j]];
        }
        double[] adjusted = Holm.adjust(family);
        double[] out = new double[p.length];
        java.util.Arrays.fill(out, Double.NaN);
        for (int j = 0; j < tested.length; j++) {
            out[tested[j]] = adjusted[j];
        }
        return out;
    }

    private static String label(String bucket, TrendBucket kind) {
        if (bucket == null) {
            return "-";
        }
        return switch (kind) {
            case DAY -> LocalDate.ofEpochDay(Long.parseLong(bucket)).toString();
            case WEEK -> LocalDate.ofEpochDay(Long.parseLong(bucket) * 7).atStartOfDay(ZoneOffset.UTC).toLocalDate()
                    .toString();
            case VERSION -> bucket;
        };
    }
}
