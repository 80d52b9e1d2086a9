package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

class RankGroupsTest {
    private static final double N = Double.NaN;

    @Test
    void onlyTheExtremePairDiffersGivesTwoOverlappingGroups() {
        // ranks (1, 2, 3); only the pair (0, 2) significant: groups {0, 1} and {1, 2} by hand
        double[][] p = {{N, 0.3, 0.01}, {0.3, N, 0.2}, {0.01, 0.2, N}};
        List<int[]> g = RankGroups.of(new double[] {1, 2, 3}, p, 0.05);
        assertEquals(2, g.size());
        assertArrayEquals(new int[] {0, 1}, g.get(0));
        assertArrayEquals(new int[] {1, 2}, g.get(1));
    }

    @Test
    void everyPairSignificantGivesNoGroupAndNoneGivesOne() {
        double[][] all = {{N, 0.01, 0.01}, {0.01, N, 0.01}, {0.01, 0.01, N}};
        assertEquals(0, RankGroups.of(new double[] {1, 2, 3}, all, 0.05).size());
        double[][] none = {{N, 0.5, 0.5}, {0.5, N, 0.5}, {0.5, 0.5, N}};
        List<int[]> g = RankGroups.of(new double[] {2.5, 1.2, 2.3}, none, 0.05);
        assertEquals(1, g.size());
        assertArrayEquals(new int[] {1, 2, 0}, g.get(0)); // in rank order
    }

    @Test
    void aPairWithoutAPValueCountsAsNotDifferent() {
        double[][] p = {{N, N, 0.01}, {N, N, 0.01}, {0.01, 0.01, N}};
        List<int[]> g = RankGroups.of(new double[] {1, 2, 3}, p, 0.05);
        assertEquals(1, g.size());
        assertArrayEquals(new int[] {0, 1}, g.get(0));
    }
}
