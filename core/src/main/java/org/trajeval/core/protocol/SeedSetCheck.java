package org.trajeval.core.protocol;

import java.util.ArrayList;
import java.util.List;
import java.util.TreeSet;

/**
 * The lesson's seed rule (section 7): methods are compared under the same seed set
 * Omega = {omega_1..omega_K}. The common set is the intersection of the methods' seed sets;
 * a method with seeds missing from, or in addition to, the suite's set is reported, and every
 * statistic is restricted to the common set.
 *
 * @param declared the suite's seed set, ascending
 * @param common the seeds every method has, ascending
 * @param deviations methods whose seeds differ from the suite's set, in manifest order
 */
public record SeedSetCheck(List<Long> declared, List<Long> common, List<Deviation> deviations) {

    /**
     * @param method the method
     * @param missing suite seeds the method lacks, ascending
     * @param extra seeds the method has beyond the suite's set, ascending
     */
    public record Deviation(String method, List<Long> missing, List<Long> extra) {
        /** @return one line, e.g. "method beta: missing seeds [3]; extra seeds [9]" */
        public String describe() {
            StringBuilder sb = new StringBuilder("method ").append(method).append(':');
            if (!missing.isEmpty()) {
                sb.append(" missing seeds ").append(missing);
            }
            if (!extra.isEmpty()) {
                sb.append(missing.isEmpty() ? " " : "; ").append("extra seeds ").append(extra);
            }
            return sb.toString();
        }
    }

    /** Copies the lists. */
    public SeedSetCheck {
        declared = List.copyOf(declared);
        common = List.copyOf(common);
        deviations = List.copyOf(deviations);
    }

    /** @return true when every method has exactly the suite's seeds */
    public boolean clean() {
        return deviations.isEmpty();
    }

    /** Checks the methods of a manifest against its seed set. */
    public static SeedSetCheck of(SuiteManifest m) {
        TreeSet<Long> declared = new TreeSet<>(m.seeds());
        TreeSet<Long> common = new TreeSet<>(declared);
        List<Deviation> devs = new ArrayList<>();
        for (MethodSpec ms : m.methods()) {
            TreeSet<Long> own = new TreeSet<>(ms.seeds());
            common.retainAll(own);
            TreeSet<Long> missing = new TreeSet<>(declared);
            missing.removeAll(own);
            TreeSet<Long> extra = new TreeSet<>(own);
            extra.removeAll(declared);
            if (!missing.isEmpty() || !extra.isEmpty()) {
                devs.add(new Deviation(ms.name(), List.copyOf(missing), List.copyOf(extra)));
            }
        }
        return new SeedSetCheck(List.copyOf(declared), List.copyOf(common), devs);
    }
}
