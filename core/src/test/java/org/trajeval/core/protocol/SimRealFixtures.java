package org.trajeval.core.protocol;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.trajeval.core.options.RunMetadata;
import org.trajeval.core.report.SuiteReport.RunEntry;

/** Small hand-made sequences and runs for the domain-gap, sweep and budget tests. */
final class SimRealFixtures {
    private SimRealFixtures() {
    }

    static SequenceSpec seq(String id, String domain, String scenario, Map<String, Double> factors) {
        return new SequenceSpec(id, id, id + ".csv", Split.TEST, List.of(), List.of(),
                new RunMetadata(domain, null, scenario, new TreeMap<>(factors), null, null, null));
    }

    static RunEntry ok(String method, String seq, long seed, double ate) {
        Map<String, Double> m = new LinkedHashMap<>();
        m.put("ate_trans_rmse_m", ate);
        return new RunEntry(method, seq, seed, "test", "x.csv", "ok", null, 1.0, m, 100.0 * (1.0 - ate), null);
    }

    static RunEntry failed(String method, String seq, long seed) {
        Map<String, Double> m = new LinkedHashMap<>();
        m.put("ate_trans_rmse_m", null);
        return new RunEntry(method, seq, seed, "test", "x.csv", "failed",
                new org.trajeval.core.report.SuiteReport.RunFailure("diverged", "x"), 1.0, m, 0.0, null);
    }

    /** Method name to runs, in insertion order. */
    static Map<String, List<RunEntry>> byMethod(List<RunEntry> runs) {
        Map<String, List<RunEntry>> out = new LinkedHashMap<>();
        for (RunEntry r : runs) {
            out.computeIfAbsent(r.method(), k -> new ArrayList<>()).add(r);
        }
        return out;
    }
}
