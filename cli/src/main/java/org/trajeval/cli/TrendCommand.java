package org.trajeval.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.time.format.DateTimeParseException;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.trajeval.core.report.ReportJson;
import org.trajeval.store.ResultsStore;
import org.trajeval.store.Selection;
import org.trajeval.store.StoredMetric;
import org.trajeval.store.Trend;
import org.trajeval.store.TrendBucket;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code trajeval trend --db URL --metric M --by SLICE}: a metric over time or versions, per slice, with flags. */
@Command(name = "trend", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"A stored metric over time (or over software versions) per robot, site, route, method or "
            + "version: per bucket the run count, the mean and its t-interval.",
            "A slice is flagged WORSE when its latest bucket is worse than its earlier buckets pooled: Welch's "
                + "one-sided t-test, Holm-adjusted across slices, at family-wise alpha = 1 - confidence."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success (flags are printed, not an error)", "1:internal error (a bug; rerun with --verbose)",
            "2:bad input (unreachable store, unknown metric or slice, bad selection)"})
public final class TrendCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Mixin
    StoreOptions store = new StoreOptions();

    @Option(names = "--metric", required = true, paramLabel = "M", description = "Metric column, e.g. "
            + "ate_trans_rmse_m (m), rpe_rot_rmse_rad (rad), drift_trans_pct (%), score, coverage.")
    String metric;

    @Option(names = "--by", required = true, paramLabel = "SLICE",
            description = "robot | site | route | method | version (or any label column).")
    String by;

    @Option(names = "--bucket", paramLabel = "B", defaultValue = "day", converter = BucketConverter.class,
            description = "day | week | version: how each slice's history is grouped (default: ${DEFAULT-VALUE}).")
    TrendBucket bucket;

    @Option(names = "--where", paramLabel = "SELECTION", description = "Only these runs: KEY=VALUE[,KEY=VALUE...].")
    String where;

    @Option(names = "--since", paramLabel = "DATE", description = "Only runs recorded on or after this UTC date "
            + "(YYYY-MM-DD).")
    String since;

    @Option(names = "--confidence", paramLabel = "C", defaultValue = "0.95",
            description = "Level of the intervals; flags at alpha = 1 - C (default: ${DEFAULT-VALUE}).")
    double confidence;

    @Option(names = "--html", paramLabel = "FILE", description = "Also write the trend as a self-contained HTML page.")
    Path html;

    @Option(names = "--verbose", description = "Print stack traces of errors.")
    boolean verbose;

    @Override
    public Integer call() {
        if (!store.given()) {
            throw UsageProblem.of("trend: --db is required");
        }
        StoredMetric.require(metric);
        long sinceMs = 0;
        if (since != null) {
            try {
                sinceMs = LocalDate.parse(since).atStartOfDay(ZoneOffset.UTC).toInstant().toEpochMilli();
            } catch (DateTimeParseException e) {
                throw UsageProblem.of("--since: expected a date YYYY-MM-DD, found \"" + since + "\"");
            }
        }
        Selection sel = where == null ? Selection.all() : Selection.parse(where, "--where");
        Trend.Result r;
        try (ResultsStore s = store.open()) {
            r = Trend.of(s, metric, by, bucket, sel, sinceMs, confidence);
        }
        PrintWriter out = spec.commandLine().getOut();
        print(r, out);
        out.flush();
        if (html != null) {
            if (store.db != null && !store.db.startsWith("jdbc:postgresql:")) {
                org.trajeval.core.io.OutputGuard.refuseInputs(html, "--html",
                        java.util.List.of(java.nio.file.Path.of(store.db.replaceFirst("^jdbc:sqlite:", ""))));
            }
            ReportJson.writeAtomically(html, TrendPage.html(r));
        }
        return ExitCodes.OK;
    }

    static void print(Trend.Result r, PrintWriter out) {
        String pct = String.format(Locale.ROOT, "%.0f%%", 100 * r.confidence());
        out.printf(Locale.ROOT, "%s by %s, per %s (%s t-interval of the mean)%n", r.metric(), r.by(),
                r.bucket().name().toLowerCase(Locale.ROOT), pct);
        out.printf(Locale.ROOT, "%-16s %-12s %7s %11s %-26s%n", r.by(), "bucket", "n", "mean", "interval " + pct);
        for (Trend.Slice s : r.slices()) {
            for (Trend.Point p : s.points()) {
                out.printf(Locale.ROOT, "%-16s %-12s %7d %11s %-26s%n", s.slice(), p.bucket(), p.n(), num(p.mean()),
                        p.interval() == null ? "-" : "[" + num(p.interval().lower()) + ", "
                                + num(p.interval().upper()) + "]");
            }
        }
        out.println();
        long flagged = r.slices().stream().filter(Trend.Slice::flagged).count();
        out.printf(Locale.ROOT, "latest bucket against the slice's history (Welch one-sided, Holm over the tested "
                + "slices, alpha %.3g): %d flagged%n", 1 - r.confidence(), flagged);
        for (Trend.Slice s : r.slices()) {
            out.printf(Locale.ROOT, "%-16s latest %s (n %d) vs history %s (n %d): p %s, Holm %s%s%n", s.slice(),
                    num(s.latest().mean()), s.latest().n(), num(s.historyMean()), s.historyN(), num(s.pValue()),
                    num(s.adjustedP()), s.flagged() ? "  WORSE" : "");
        }
    }

    static String num(double v) {
        return Double.isFinite(v) ? String.format(Locale.ROOT, "%.4g", v) : "-";
    }

    /** day|week|version. */
    static final class BucketConverter implements picocli.CommandLine.ITypeConverter<TrendBucket> {
        @Override
        public TrendBucket convert(String v) {
            return EnumWords.parse(TrendBucket.class, v, "day|week|version");
        }
    }
}
