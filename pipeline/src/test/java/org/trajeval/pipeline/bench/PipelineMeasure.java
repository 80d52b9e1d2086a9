package org.trajeval.pipeline.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.trajeval.pipeline.CoreRunScorer;
import org.trajeval.pipeline.Fixtures;
import org.trajeval.pipeline.PipelineCommand;
import org.trajeval.pipeline.ReportStore;
import org.trajeval.pipeline.RunProcessor;
import org.trajeval.pipeline.bundle.BundleLimits;
import org.trajeval.pipeline.bundle.BundleOpener;
import org.trajeval.pipeline.dir.Completion;
import org.trajeval.pipeline.dir.DirectoryLayout;
import org.trajeval.pipeline.dir.DirectoryOptions;
import org.trajeval.pipeline.dir.DirectoryService;
import org.trajeval.pipeline.dir.DrainSummary;
import org.trajeval.pipeline.ledger.Ledger;
import org.trajeval.pipeline.metrics.PipelineMetrics;

/**
 * Measures the figures of the README (not a test): throughput in runs/s for 10 000-pose runs
 * (in-process directory service, real scorer), and the memory of the service (a child JVM, as
 * the launcher runs it) draining a backlog of 10 000 bundles. Run with {@code gradle :pipeline:measure}.
 */
public final class PipelineMeasure {
    private PipelineMeasure() {
    }

    /** @param args [runs of 10 000 poses, default 100] [backlog bundles, default 10000] [workers, default 2] */
    public static void main(String[] args) throws Exception {
        int runs = args.length > 0 ? Integer.parseInt(args[0]) : 100;
        int backlog = args.length > 1 ? Integer.parseInt(args[1]) : 10_000;
        int workers = args.length > 2 ? Integer.parseInt(args[2]) : 2;
        Path tmp = Files.createTempDirectory("trajeval-measure");
        try {
            throughput(tmp.resolve("throughput"), runs, workers);
            backlog(tmp.resolve("backlog"), backlog, workers);
        } finally {
            Fixtures.deleteTree(tmp);
        }
    }

    private static void throughput(Path root, int runs, int workers) throws IOException {
        DirectoryLayout layout = new DirectoryLayout(root).create();
        for (int i = 0; i < runs; i++) {
            Fixtures.pair(layout.incoming(), "run-" + i, 10_000, i);
            Fixtures.marker(layout.incoming(), "run-" + i);
        }
        long bytes = Files.size(layout.incoming().resolve("run-0.gt.csv"));
        try (Ledger ledger = Ledger.open(layout.ledger())) {
            DirectoryService s = new DirectoryService(layout,
                    new DirectoryOptions(workers, workers, Completion.MARKER, java.time.Duration.ofSeconds(60),
                            java.time.Duration.ofMillis(100)),
                    new RunProcessor(new CoreRunScorer(1L << 30), new ReportStore(layout.reports(), ledger, Clock.systemUTC())),
                    new BundleOpener(BundleLimits.DEFAULTS), PipelineMetrics.inMemory(), Clock.systemUTC());
            long t0 = System.nanoTime();
            DrainSummary sum = s.drain();
            double sec = (System.nanoTime() - t0) / 1e9;
            System.out.printf(Locale.ROOT, "throughput: %d runs of 10000 poses (%d KB per file), %d workers: %.1f s, %.1f runs/s (%s)%n",
                    runs, bytes / 1024, workers, sec, runs / sec, sum);
        }
    }

    private static void backlog(Path root, int bundles, int workers) throws Exception {
        DirectoryLayout layout = new DirectoryLayout(root).create();
        for (int i = 0; i < bundles; i++) {
            Fixtures.pair(layout.incoming(), "run-" + i, 200, i);
            Fixtures.marker(layout.incoming(), "run-" + i);
        }
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx128m", "-cp", System.getProperty("trajeval.testClasspath", System.getProperty("java.class.path")),
                PipelineCommand.class.getName(), "watch", "--root", root.toString(), "--drain", "--workers",
                String.valueOf(workers)));
        long t0 = System.nanoTime();
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(ProcessBuilder.Redirect.appendTo(root.resolve("service.log").toFile())).start();
        long peakKb = 0;
        while (p.isAlive()) {
            peakKb = Math.max(peakKb, vmHwmKb(p.pid()));
            Thread.sleep(200);
        }
        double sec = (System.nanoTime() - t0) / 1e9;
        System.out.printf(Locale.ROOT, "backlog: %d bundles of 200 poses drained with -Xmx128m, %d workers: exit %d, %.1f s "
                + "(%.0f runs/s incl. JVM start), peak RSS %d MiB%n", bundles, workers, p.exitValue(), sec, bundles / sec,
                peakKb / 1024);
        System.out.println("  service output: " + Files.readString(root.resolve("service.log")).trim()
                .lines().reduce((a, b) -> b).orElse(""));
    }

    private static long vmHwmKb(long pid) {
        try {
            for (String line : Files.readAllLines(Path.of("/proc/" + pid + "/status"))) {
                if (line.startsWith("VmHWM:")) {
                    return Long.parseLong(line.replaceAll("[^0-9]", ""));
                }
            }
        } catch (IOException | NumberFormatException e) {
            // the process has just ended
        }
        return 0;
    }
}
