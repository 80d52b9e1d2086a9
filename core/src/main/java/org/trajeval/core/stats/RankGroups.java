package org.trajeval.core.stats;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The bars of an average-rank ("critical difference") diagram drawn from pairwise tests (Demsar
 * 2006; Benavoli, Corani and Mangili 2016, J. Mach. Learn. Res. 17:1-10, who recommend pairwise
 * Wilcoxon tests with Holm's correction over the Nemenyi critical difference). Methods are
 * ordered by average rank; a group is a maximal run of consecutive methods in that order of
 * which no pair differs significantly (adjusted p &gt;= alpha). A pair without a p-value (no
 * common sequence) counts as not different. Worked example: ranks (1, 2, 3) with only the pair
 * (1, 3) significant give the groups {1, 2} and {2, 3}.
 */
public final class RankGroups {
    private RankGroups() {
    }

    /**
     * @param averageRanks R_j per method
     * @param adjustedP adjusted p-value of each pair, adjustedP[a][b] = adjustedP[b][a] (NaN: unknown)
     * @param alpha significance level
     * @return the groups, each the method indices in rank order, at least two per group
     */
    public static List<int[]> of(double[] averageRanks, double[][] adjustedP, double alpha) {
        int k = averageRanks.length;
        Integer[] order = new Integer[k];
        for (int i = 0; i < k; i++) {
            order[i] = i;
        }
        Arrays.sort(order, (a, b) -> Double.compare(averageRanks[a], averageRanks[b]));
        List<int[]> groups = new ArrayList<>();
        int lastEnd = -1;
        for (int i = 0; i < k; i++) {
            int j = i;
            while (j + 1 < k && alike(order, i, j + 1, adjustedP, alpha)) {
                j++;
            }
            if (j > i && j > lastEnd) {
                int[] g = new int[j - i + 1];
                for (int t = i; t <= j; t++) {
                    g[t - i] = order[t];
                }
                groups.add(g);
                lastEnd = j;
            }
        }
        return groups;
    }

    /** @return true when method order[next] differs significantly from none of order[from..next-1] */
    private static boolean alike(Integer[] order, int from, int next, double[][] p, double alpha) {
        for (int t = from; t < next; t++) {
            double v = p[order[t]][order[next]];
            if (v < alpha) {
                return false;
            }
        }
        return true;
    }
}
