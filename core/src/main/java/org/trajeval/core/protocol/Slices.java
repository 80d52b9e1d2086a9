package org.trajeval.core.protocol;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.trajeval.core.options.RunMetadata;
import org.trajeval.core.report.SliceReport;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.RunEntry;

/**
 * The methods' tables per value of each description field ({@link RunMetadata#SLICE_DIMENSIONS}:
 * domain, environment, modality, ground_truth): the same summary as the report's {@code methods}
 * ({@link SuiteAnalysis#summarise}), over the runs on the sequences of that value only. A dimension
 * no sequence declares gives no slice; sequences without a value are in no slice of it.
 */
public final class Slices {
    private Slices() {
    }

    /**
     * @param sequences the evaluated sequences
     * @param runsByMethod every method's runs, in manifest order
     * @param metricKeys the score metrics' keys
     * @param level confidence level of the failure-rate intervals
     * @return slices by dimension (table order), then value (sorted)
     */
    public static List<SliceReport> compute(List<SequenceSpec> sequences, Map<String, List<RunEntry>> runsByMethod,
            List<String> metricKeys, double level) {
        List<SliceReport> out = new ArrayList<>();
        for (String dim : RunMetadata.SLICE_DIMENSIONS) {
            Map<String, List<String>> byValue = new TreeMap<>();
            for (SequenceSpec s : sequences) {
                String v = s.about().slice(dim);
                if (v != null) {
                    byValue.computeIfAbsent(v, k -> new ArrayList<>()).add(s.id());
                }
            }
            byValue.forEach((value, ids) -> {
                List<SuiteReport.MethodSummary> methods = new ArrayList<>();
                Map<String, List<RunEntry>> in = new LinkedHashMap<>();
                runsByMethod.forEach((m, runs) -> in.put(m, runs.stream().filter(r -> ids.contains(r.sequence()))
                        .toList()));
                in.forEach((m, runs) -> methods.add(SuiteAnalysis.summarise(m, ids, runs, metricKeys, level)));
                out.add(new SliceReport(dim, value, ids, methods));
            });
        }
        return out;
    }
}
