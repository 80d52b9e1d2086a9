package org.trajeval.core.options;

import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * What one run cost, as measured by whoever ran the method: the fields of a suite's resources
 * table row, and of {@code resources:} in a run.yaml or Kafka run event
 * ({@code resources: {wall_time_s: 41.2, peak_memory_mib: 812, cpu_time_s: 75.0, device: cpu}}).
 *
 * @param wallTimeS wall-clock time (s, &gt; 0)
 * @param peakMemoryMib peak resident memory (MiB, &ge; 0)
 * @param cpuTimeS CPU time (s, &ge; 0), or null
 * @param device cpu or gpu, or null
 */
public record RunResources(double wallTimeS, double peakMemoryMib, Double cpuTimeS, String device) {
    private static final Set<String> KEYS = Set.of("wall_time_s", "peak_memory_mib", "cpu_time_s", "device");

    /**
     * @param tree the {@code resources} mapping (values from YAML or JSON), or null
     * @param where its key path ({@code resources})
     * @param source the file or event, for refusals
     * @return the resources, or null when absent
     * @throws InputException (INVALID_CONFIGURATION) naming the field
     */
    public static RunResources parse(Object tree, String where, String source) {
        if (tree == null) {
            return null;
        }
        if (!(tree instanceof Map<?, ?> m)) {
            throw bad(source, where, "expected a mapping {wall_time_s, peak_memory_mib, cpu_time_s, device}", tree);
        }
        for (Object k : m.keySet()) {
            if (!KEYS.contains(String.valueOf(k))) {
                throw bad(source, where + "." + k, "unknown key; expected one of " + String.join(", ",
                        new TreeSet<>(KEYS)), k);
            }
        }
        Double wall = number(m.get("wall_time_s"), where + ".wall_time_s", source, true, true);
        Double mem = number(m.get("peak_memory_mib"), where + ".peak_memory_mib", source, false, true);
        Double cpu = number(m.get("cpu_time_s"), where + ".cpu_time_s", source, false, false);
        String device = null;
        Object d = m.get("device");
        if (d != null) {
            device = String.valueOf(d).trim().toLowerCase(Locale.ROOT);
            if (!device.equals("cpu") && !device.equals("gpu")) {
                throw bad(source, where + ".device", "expected cpu or gpu", d);
            }
        }
        return new RunResources(wall, mem, cpu, device);
    }

    private static Double number(Object v, String where, String source, boolean positive, boolean required) {
        if (v == null) {
            if (required) {
                throw bad(source, where, "required key is missing", null);
            }
            return null;
        }
        if (!(v instanceof Number n) || !Double.isFinite(n.doubleValue())
                || (positive ? n.doubleValue() <= 0.0 : n.doubleValue() < 0.0)) {
            throw bad(source, where, "expected a finite number " + (positive ? "> 0" : ">= 0")
                    + (where.endsWith("_mib") ? " (MiB)" : " (s)"), v);
        }
        return n.doubleValue();
    }

    private static InputException bad(String source, String where, String expected, Object found) {
        return new InputException(source, 0, where, InputProblem.INVALID_CONFIGURATION, "'" + where + "': " + expected,
                found == null ? null : String.valueOf(found));
    }
}
