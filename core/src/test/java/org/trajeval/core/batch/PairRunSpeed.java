package org.trajeval.core.batch;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.options.SettingText;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ReportJson;

/**
 * Not a test: scores the first PAIRS pairs of an {@code eval --batch} table ROUNDS times in one JVM
 * on one thread, each as {@code eval --batch} does (read both files, evaluate with
 * {@code --convention CONVENTION}, report JSON, report written atomically into OUT), and prints each
 * round's thread CPU time per pair (us), split into read + evaluate, JSON and writing. The first
 * rounds include the JIT's warm-up. Usage, with the launcher's jars:
 * {@code java -cp core/build/classes/java/test:cli/build/install/trajeval/lib/*
 * org.trajeval.core.batch.PairRunSpeed PAIRS.csv PAIRS ROUNDS OUT [lesson|evo|kitti]}.
 */
public final class PairRunSpeed {
    private PairRunSpeed() {
    }

    public static void main(String[] args) throws Exception {
        Path table = Path.of(args[0]);
        List<BatchPair> all = PairsTable.read(table, 256L << 20);
        List<BatchPair> pairs = all.subList(0, Math.min(all.size(), Integer.parseInt(args[1])));
        int rounds = Integer.parseInt(args[2]);
        Path out = Files.createDirectories(Path.of(args[3]));
        String convention = args.length > 4 ? args[4] : "lesson";
        SettingValues settings = SettingValues.of(List.of(new SettingText("convention", convention, "--convention")),
                "command line");
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        StringBuilder line = new StringBuilder();
        long best = Long.MAX_VALUE;
        for (int r = 0; r < rounds; r++) {
            long eval = 0;
            long json = 0;
            long write = 0;
            for (BatchPair pair : pairs) {
                long c0 = mx.getCurrentThreadCpuTime();
                EvaluationReport report = BatchRunner.evaluate(pair, settings, table + ":" + pair.line(),
                        ReadOptions.defaults(), (text, where) -> table.toAbsolutePath().getParent().resolve(text));
                long c1 = mx.getCurrentThreadCpuTime();
                String text = ReportJson.toJson(report) + "\n";
                long c2 = mx.getCurrentThreadCpuTime();
                BatchResult row = ReportWriter.writeNow(pair, report, text, out);
                long c3 = mx.getCurrentThreadCpuTime();
                if (!row.ok()) {
                    throw new IllegalStateException(row.failureDetail());
                }
                eval += c1 - c0;
                json += c2 - c1;
                write += c3 - c2;
            }
            long n = pairs.size();
            long total = (eval + json + write) / n / 1000;
            best = Math.min(best, total);
            line.append(String.format(Locale.ROOT, " %d(%d+%d+%d)", total, eval / n / 1000, json / n / 1000,
                    write / n / 1000));
        }
        System.out.printf(Locale.ROOT, "%d pairs, us CPU per pair by round, total(read+eval, json, write):%s | best %d us%n",
                pairs.size(), line, best);
    }
}
