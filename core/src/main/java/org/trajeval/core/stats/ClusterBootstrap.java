package org.trajeval.core.stats;

import java.util.SplittableRandom;

/**
 * Resampling plans of a stratified cluster bootstrap, as counts per unit. Units (e.g. sequences)
 * are grouped into clusters (e.g. the sim and the real sequence of one scenario), clusters into
 * strata (e.g. the sim and the real domain when nothing pairs them). Each resample draws, in every
 * stratum, as many clusters as the stratum has, with replacement; a unit's count is how often its
 * cluster was drawn. A statistic evaluated with these counts as weights gives the bootstrap
 * replicates; the same plans applied to several statistics keep them paired. Seeded: the same
 * strata, B and seed give the same plans on every machine.
 */
public final class ClusterBootstrap {
    private ClusterBootstrap() {
    }

    /**
     * @param units number of units (indices 0 .. units-1)
     * @param strata per stratum, its clusters, each an array of unit indices
     * @param resamples number of resamples B (at least 100)
     * @param seed seed of the resampling
     * @return counts[b][unit]
     * @throws IllegalArgumentException on too few resamples or an empty stratum
     */
    public static int[][] plans(int units, int[][][] strata, int resamples, long seed) {
        if (resamples < 100) {
            throw new IllegalArgumentException("bootstrap needs at least 100 resamples, got " + resamples);
        }
        for (int[][] s : strata) {
            if (s.length == 0) {
                throw new IllegalArgumentException("a stratum without clusters");
            }
        }
        SplittableRandom rng = new SplittableRandom(seed);
        int[][] out = new int[resamples][units];
        for (int b = 0; b < resamples; b++) {
            for (int[][] stratum : strata) {
                for (int draw = 0; draw < stratum.length; draw++) {
                    for (int unit : stratum[rng.nextInt(stratum.length)]) {
                        out[b][unit]++;
                    }
                }
            }
        }
        return out;
    }
}
