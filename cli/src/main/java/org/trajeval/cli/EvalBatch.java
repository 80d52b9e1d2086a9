package org.trajeval.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;
import org.trajeval.core.batch.BatchPair;
import org.trajeval.core.batch.BatchResult;
import org.trajeval.core.batch.BatchRunner;
import org.trajeval.core.batch.BatchSummary;
import org.trajeval.core.batch.PairsTable;
import org.trajeval.core.io.OutputGuard;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.options.SettingValues;

/**
 * {@code trajeval eval --batch PAIRS.csv --reports DIR}: many pairs in one JVM. One report per
 * pair ({@code DIR/NAME.json}) and {@code DIR/summary.csv}; a pair that cannot be scored is a
 * failed row (one stderr line each) and the batch goes on. Exit 0 when every pair was scored,
 * {@value ExitCodes#SOME_FAILED} when some failed on their input (or their report could not be
 * written), 1 when one failed on an internal error, 2 when the table itself or an option is bad
 * (nothing scored).
 */
final class EvalBatch {
    /** Largest pairs table read (bytes). */
    static final long MAX_TABLE_BYTES = 256L << 20;

    private EvalBatch() {
    }

    static int run(Path table, Path reportDir, SettingValues settings, ReadOptions limits, int threads,
            PrintWriter out, PrintWriter err) {
        if (reportDir == null) {
            throw UsageProblem.of("--reports", "--batch needs --reports DIR: the folder for one report per pair and "
                    + "summary.csv", null);
        }
        List<BatchPair> pairs = PairsTable.read(table, MAX_TABLE_BYTES);
        OutputGuard.refuseFolderOfInputs(reportDir, "--reports", List.of(table));
        if (Files.exists(reportDir) && !Files.isDirectory(reportDir)) {
            throw UsageProblem.of("--reports", "--reports must name a folder; this is a file", reportDir.toString());
        }
        long start = System.nanoTime();
        AtomicInteger failed = new AtomicInteger();
        List<BatchResult> rows;
        try (EvalThreads work = new EvalThreads(threads)) {
            rows = BatchRunner.run(pairs, settings, table.toString(), limits,
                    (text, where) -> table.toAbsolutePath().getParent().resolve(text), reportDir, work.parallelism(),
                    r -> {
                        if (!r.ok()) {
                            failed.incrementAndGet();
                            synchronized (err) {
                                err.println("trajeval: " + table + ":" + r.pair().line() + ": pair not scored ("
                                        + r.failureReason() + "): " + r.failureDetail());
                                err.flush();
                            }
                        }
                    });
        }
        double s = (System.nanoTime() - start) / 1e9;
        boolean internal = rows.stream().anyMatch(BatchResult::internalError);
        out.printf(Locale.ROOT, "scored %d of %d pairs in %.1f s (%.1f pairs/s), %d failed; reports and %s in %s%n",
                rows.size() - failed.get(), rows.size(), s, rows.size() / Math.max(s, 1e-9), failed.get(),
                BatchSummary.FILE, reportDir);
        out.flush();
        return internal ? ExitCodes.INTERNAL : failed.get() > 0 ? ExitCodes.SOME_FAILED : ExitCodes.OK;
    }
}
