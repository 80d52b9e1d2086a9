package org.trajeval.core.protocol;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import org.trajeval.core.report.FactorSweep;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.RunEntry;
import org.trajeval.core.stats.KendallTau;
import org.trajeval.core.stats.MedianInterval;

/**
 * Stress sweeps (lesson section 8: "controlled variation of one factor at a time"). For each factor
 * declared by an evaluated sequence, per method and level x: the runs on the sequences at x, their
 * failure rate with its intervals ({@link SuiteAnalysis#failureRate}), and per metric the median
 * with its order-statistic interval ({@link MedianInterval}) over the successful runs (every run for
 * the score, a failure scoring 0). A method's breakdown level is the lowest x whose failure rate
 * f/n reaches {@code failure.breakdown_rate}. Its sensitivity to the factor is Kendall's tau_b
 * between level and value over the runs (positive: the value grows with the level). Worked example:
 * failure rates 0, 0.2, 0.6, 1.0 at levels 0, 0.2, 0.4, 0.6 and breakdown rate 0.5 give breakdown
 * level 0.4.
 */
public final class FactorSweeps {
    private FactorSweeps() {
    }

    /**
     * @param sequences the evaluated sequences
     * @param runsByMethod every method's runs, in manifest order
     * @param keys the compared metrics (score metrics and the score)
     * @param level confidence level
     * @param breakdownRate failure rate of a breakdown, in (0, 1]
     * @return one sweep per factor, sorted by factor name
     */
    public static List<FactorSweep> compute(List<SequenceSpec> sequences, Map<String, List<RunEntry>> runsByMethod,
            List<String> keys, double level, double breakdownRate) {
        Set<String> factors = new TreeSet<>();
        sequences.forEach(s -> factors.addAll(s.about().factors().keySet()));
        List<FactorSweep> out = new ArrayList<>();
        for (String factor : factors) {
            List<SequenceSpec> in = sequences.stream().filter(s -> s.about().factors().containsKey(factor)).toList();
            TreeSet<Double> levels = new TreeSet<>();
            in.forEach(s -> levels.add(s.about().factors().get(factor)));
            List<FactorSweep.MethodSweep> methods = new ArrayList<>();
            for (Map.Entry<String, List<RunEntry>> e : runsByMethod.entrySet()) {
                List<FactorSweep.Level> rows = new ArrayList<>();
                Double breakdown = null;
                for (double x : levels) {
                    List<String> at = in.stream().filter(s -> s.about().factors().get(factor) == x)
                            .map(SequenceSpec::id).toList();
                    List<RunEntry> runs = e.getValue().stream().filter(r -> at.contains(r.sequence())).toList();
                    SuiteReport.Proportion rate = SuiteAnalysis.failureRate(at, runs, level);
                    int failures = (int) runs.stream().filter(r -> !r.ok()).count();
                    if (breakdown == null && rate != null && rate.estimate() >= breakdownRate) {
                        breakdown = x;
                    }
                    List<FactorSweep.LevelMetric> metrics = new ArrayList<>();
                    for (String key : keys) {
                        double[] v = values(runs, at, key);
                        if (v.length == 0) {
                            metrics.add(new FactorSweep.LevelMetric(key, 0, null, null, null, null));
                        } else {
                            MedianInterval.Result m = MedianInterval.of(v, level);
                            metrics.add(new FactorSweep.LevelMetric(key, v.length, m.median(), m.interval().lower(),
                                    m.interval().upper(), m.achievedLevel()));
                        }
                    }
                    rows.add(new FactorSweep.Level(x, at.size(), runs.size(), failures, rate, metrics));
                }
                List<FactorSweep.Sensitivity> sens = new ArrayList<>();
                for (String key : keys) {
                    List<double[]> pairs = new ArrayList<>();
                    for (SequenceSpec s : in) {
                        for (double v : SuiteAnalysis.values(e.getValue(), s.id(), key)) {
                            pairs.add(new double[] {s.about().factors().get(factor), v});
                        }
                    }
                    double tau = KendallTau.tauB(pairs.stream().mapToDouble(p -> p[0]).toArray(),
                            pairs.stream().mapToDouble(p -> p[1]).toArray());
                    sens.add(new FactorSweep.Sensitivity(key, pairs.size(), SuiteAnalysis.nullable(tau)));
                }
                methods.add(new FactorSweep.MethodSweep(e.getKey(), rows, breakdown, sens));
            }
            out.add(new FactorSweep(factor, in.stream().map(SequenceSpec::id).toList(), new ArrayList<>(levels),
                    breakdownRate, methods));
        }
        return out;
    }

    private static double[] values(List<RunEntry> runs, List<String> sequences, String key) {
        List<Double> out = new ArrayList<>();
        for (String s : sequences) {
            for (double v : SuiteAnalysis.values(runs, s, key)) {
                out.add(v);
            }
        }
        return out.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /**
     * Pairs of a sweep's sequences that differ in more than one factor (a factor missing on one side
     * counts as a difference): the sweep then does not vary one factor at a time.
     *
     * @return one warning per factor with such pairs (at most 3 pairs named, the rest counted)
     */
    public static List<String> oneFactorAtATimeWarnings(List<SequenceSpec> sequences) {
        Set<String> factors = new TreeSet<>();
        sequences.forEach(s -> factors.addAll(s.about().factors().keySet()));
        List<String> out = new ArrayList<>();
        for (String factor : factors) {
            List<SequenceSpec> in = sequences.stream().filter(s -> s.about().factors().containsKey(factor)).toList();
            List<String> pairs = new ArrayList<>();
            for (int i = 0; i < in.size(); i++) {
                for (int j = i + 1; j < in.size(); j++) {
                    Set<String> differ = new TreeSet<>();
                    Map<String, Double> a = in.get(i).about().factors();
                    Map<String, Double> b = in.get(j).about().factors();
                    Set<String> names = new TreeSet<>(a.keySet());
                    names.addAll(b.keySet());
                    for (String n : names) {
                        if (!a.containsKey(n) || !b.containsKey(n) || !a.get(n).equals(b.get(n))) {
                            differ.add(n);
                        }
                    }
                    if (differ.size() > 1) {
                        pairs.add(in.get(i).id() + " and " + in.get(j).id() + " differ in " + String.join(", ", differ));
                    }
                }
            }
            if (!pairs.isEmpty()) {
                out.add("FACTORS: the sweep of '" + factor + "' does not vary one factor at a time: "
                        + String.join("; ", pairs.subList(0, Math.min(3, pairs.size())))
                        + (pairs.size() > 3 ? "; and " + (pairs.size() - 3) + " more pair(s)" : ""));
            }
        }
        return out;
    }
}
