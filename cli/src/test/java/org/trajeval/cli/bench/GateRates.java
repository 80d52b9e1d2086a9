package org.trajeval.cli.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import org.trajeval.core.protocol.DemoBenchmark;
import org.trajeval.core.protocol.RegressionGate;
import org.trajeval.core.protocol.RunEngine;
import org.trajeval.core.protocol.SuiteRunner;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.RunEntry;

/**
 * The README's gate figures: {@code gradle :cli:gateRates [-Pargs="N"]}. Runs the demo suite on N
 * data seeds (new synthetic data each time, the same three methods of the same quality), then
 * gates every pair of suites (baseline = lower seed) with the defaults (score metrics at 5 %,
 * one-sided 95 %): the share of gates that fail is the false-alarm rate. Detection: the same pairs
 * with the candidate's alpha made worse by a factor 1 + delta on every run's ATE and RPE (the
 * metric values are scaled; the trajectories are not regenerated); the share of gates that flag
 * alpha is the detection rate at that delta.
 */
public final class GateRates {
    private static final List<String> METRICS = List.of("ate_trans_rmse_m", "rpe_trans_rmse_m");

    private GateRates() {
    }

    public static void main(String[] args) throws Exception {
        int n = args.length > 0 ? Integer.parseInt(args[0]) : 30;
        Path tmp = Files.createTempDirectory("trajeval-gate-rates");
        List<SuiteReport> suites = new ArrayList<>();
        ExecutorService pool = Executors.newFixedThreadPool(2);
        long t0 = System.nanoTime();
        try {
            for (int s = 1; s <= n; s++) {
                Path dir = tmp.resolve("s" + s);
                Path manifest = DemoBenchmark.write(dir, s);
                suites.add(new SuiteRunner(RunEngine.standard(), pool, SuiteRunner.Progress.none())
                        .run(manifest, new SuiteRunner.Settings(s, true, 0.95, 1000)).report());
                deleteTree(dir);
            }
        } finally {
            pool.shutdownNow();
            deleteTree(tmp);
        }
        System.out.printf(Locale.ROOT, "%d demo suites (data seeds 1-%d) in %.0f s%n", n, n,
                (System.nanoTime() - t0) / 1e9);
        RegressionGate.Settings settings = new RegressionGate.Settings(0.95, 1, 4000);
        Map<String, Double> tol = new LinkedHashMap<>();
        METRICS.forEach(m -> tol.put(m, 0.05));
        double[] deltas = {0.0, 0.05, 0.10, 0.20, 0.30, 0.50};
        int pairs = 0;
        int[] failedGates = new int[deltas.length];
        int[] alphaFlagged = new int[deltas.length];
        int findings = 0;
        int falseFindings = 0;
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                pairs++;
                SuiteReport b = suites.get(i);
                SuiteReport c = suites.get(j);
                List<String> seqs = b.protocol().sequences().stream()
                        .filter(s -> b.protocol().evaluatedSplits().contains(s.split())).map(s -> s.id()).toList();
                List<String> methods = b.methods().stream().map(SuiteReport.MethodSummary::name).toList();
                for (int d = 0; d < deltas.length; d++) {
                    List<RunEntry> cand = degradeAlpha(c.runs(), deltas[d]);
                    List<RegressionGate.Finding> fs = RegressionGate.gateAll(b.runs(), cand, methods, seqs, tol,
                            settings);
                    if (fs.stream().anyMatch(f -> f.verdict() == RegressionGate.Verdict.REGRESSION)) {
                        failedGates[d]++;
                    }
                    if (fs.stream().anyMatch(f -> f.method().equals("alpha")
                            && f.verdict() == RegressionGate.Verdict.REGRESSION)) {
                        alphaFlagged[d]++;
                    }
                    if (d == 0) {
                        findings += fs.size();
                        falseFindings += (int) fs.stream()
                                .filter(f -> f.verdict() == RegressionGate.Verdict.REGRESSION).count();
                    }
                }
            }
        }
        System.out.printf(Locale.ROOT, "%d gates (every pair of suites), %d findings each (3 methods x 2 metrics)%n",
                pairs, 2 * 3);
        System.out.printf(Locale.ROOT, "false alarms: %d of %d gates failed (%.1f %%); %d of %d findings (%.2f %%)%n",
                failedGates[0], pairs, 100.0 * failedGates[0] / pairs, falseFindings, findings,
                100.0 * falseFindings / findings);
        for (int d = 1; d < deltas.length; d++) {
            System.out.printf(Locale.ROOT, "alpha %.0f %% worse: alpha flagged in %d of %d gates (%.1f %%)%n",
                    100 * deltas[d], alphaFlagged[d], pairs, 100.0 * alphaFlagged[d] / pairs);
        }
    }

    private static List<RunEntry> degradeAlpha(List<RunEntry> runs, double delta) {
        if (delta == 0) {
            return runs;
        }
        List<RunEntry> out = new ArrayList<>(runs.size());
        for (RunEntry r : runs) {
            if (!r.method().equals("alpha") || r.metrics() == null) {
                out.add(r);
                continue;
            }
            Map<String, Double> m = new HashMap<>(r.metrics());
            for (String k : METRICS) {
                if (m.get(k) != null) {
                    m.put(k, m.get(k) * (1 + delta));
                }
            }
            out.add(new RunEntry(r.method(), r.sequence(), r.seed(), r.split(), r.estimate(), r.status(), r.failure(),
                    r.coverage(), m, r.score(), null));
        }
        return out;
    }

    private static void deleteTree(Path root) throws java.io.IOException {
        if (!Files.exists(root)) {
            return;
        }
        try (var s = Files.walk(root)) {
            s.sorted(java.util.Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        }
    }
}
