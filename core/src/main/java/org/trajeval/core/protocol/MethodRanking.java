package org.trajeval.core.protocol;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.Comparison;
import org.trajeval.core.report.SuiteReport.Ranking;
import org.trajeval.core.report.SuiteReport.RunEntry;
import org.trajeval.core.stats.FriedmanTest;
import org.trajeval.core.stats.Holm;
import org.trajeval.core.stats.RankGroups;
import org.trajeval.core.stats.SampleSummary;

/**
 * Many methods at once. Per metric, the pairwise Wilcoxon p-values form one family, adjusted by
 * Holm's method (so "A beats B" claims over all pairs of a metric keep a family-wise error rate of
 * alpha); with three or more methods, the Friedman test and the Iman-Davenport F over the
 * sequences where every method has a value (its per-sequence mean over its own successful seeds;
 * for the score every run counts), the average ranks (1 = best) and the groups of the
 * average-rank diagram, drawn from the Holm-adjusted pairwise tests at alpha = 1 - confidence.
 */
public final class MethodRanking {
    private MethodRanking() {
    }

    /**
     * @param comparisons the comparisons with their Holm-adjusted p-values, in the input order
     * @param rankings one ranking per metric with three or more methods, else empty
     */
    public record Result(List<Comparison> comparisons, List<Ranking> rankings) {
    }

    /**
     * @param methods method names in report order
     * @param runs each method's runs
     * @param sequences evaluated sequences in report order
     * @param keys compared metric keys in report order (including {@link SuiteAnalysis#SCORE})
     * @param comparisons the pairwise comparisons of every metric
     * @param level confidence level; groups use alpha = 1 - level
     */
    public static Result of(List<String> methods, Map<String, List<RunEntry>> runs, List<String> sequences,
            List<String> keys, List<Comparison> comparisons, double level) {
        List<Comparison> adjusted = new ArrayList<>(comparisons);
        List<Ranking> rankings = new ArrayList<>();
        for (String key : keys) {
            List<Integer> family = new ArrayList<>();
            for (int i = 0; i < comparisons.size(); i++) {
                if (comparisons.get(i).metric().equals(key) && comparisons.get(i).wilcoxon() != null) {
                    family.add(i);
                }
            }
            double[] raw = family.stream().mapToDouble(i -> comparisons.get(i).wilcoxon().pValue()).toArray();
            double[] adj = Holm.adjust(raw);
            String name = familyName(key, family.size());
            for (int f = 0; f < family.size(); f++) {
                int i = family.get(f);
                adjusted.set(i, comparisons.get(i).withHolm(new SuiteReport.HolmAdjusted(name, family.size(),
                        adj[f])));
            }
            if (methods.size() >= 3) {
                rankings.add(rank(methods, runs, sequences, key, adjusted, name, 1.0 - level));
            }
        }
        return new Result(adjusted, rankings);
    }

    /** @return the name of the Holm family of one metric */
    public static String familyName(String key, int m) {
        return "pairwise Wilcoxon signed-rank tests on " + key + " (" + m + (m == 1 ? " test" : " tests")
                + "), Holm";
    }

    private static Ranking rank(List<String> methods, Map<String, List<RunEntry>> runs, List<String> sequences,
            String key, List<Comparison> comparisons, String family, double alpha) {
        int k = methods.size();
        List<double[]> blocks = new ArrayList<>();
        for (String s : sequences) {
            double[] row = new double[k];
            boolean complete = true;
            for (int j = 0; j < k && complete; j++) {
                double[] v = SuiteAnalysis.values(runs.get(methods.get(j)), s, key);
                complete = v.length > 0;
                row[j] = complete ? SampleSummary.of(v).mean() : Double.NaN;
            }
            if (complete) {
                blocks.add(row);
            }
        }
        boolean higher = SuiteAnalysis.SCORE.equals(key);
        List<SuiteReport.RankedMethod> ranked = new ArrayList<>();
        if (blocks.size() < 2) {
            for (String m : methods) {
                ranked.add(new SuiteReport.RankedMethod(m, null));
            }
            return new Ranking(key, higher ? "higher" : "lower", blocks.size(), ranked, null, null, family, alpha,
                    List.of());
        }
        FriedmanTest.Result fr = FriedmanTest.of(blocks.toArray(new double[0][]), !higher);
        double[] avg = fr.averageRanks();
        for (int j = 0; j < k; j++) {
            ranked.add(new SuiteReport.RankedMethod(methods.get(j), avg[j]));
        }
        double[][] p = new double[k][k];
        for (double[] row : p) {
            java.util.Arrays.fill(row, Double.NaN);
        }
        for (Comparison c : comparisons) {
            int a = methods.indexOf(c.methodA());
            int b = methods.indexOf(c.methodB());
            if (c.metric().equals(key) && a >= 0 && b >= 0 && c.holm() != null) {
                p[a][b] = c.holm().pAdjusted();
                p[b][a] = c.holm().pAdjusted();
            }
        }
        List<List<String>> groups = new ArrayList<>();
        for (int[] g : RankGroups.of(avg, p, alpha)) {
            List<String> names = new ArrayList<>();
            for (int j : g) {
                names.add(methods.get(j));
            }
            groups.add(names);
        }
        SuiteReport.RankTest chi = new SuiteReport.RankTest(fr.chiSquare(), fr.df(), null, fr.chiSquareP());
        SuiteReport.RankTest id = new SuiteReport.RankTest(SuiteAnalysis.nullable(fr.imanDavenport()), fr.df(),
                fr.dfDenominator(), fr.imanDavenportP());
        return new Ranking(key, higher ? "higher" : "lower", blocks.size(), ranked, chi, id, family, alpha, groups);
    }
}
