package org.trajeval.core.stats;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;

/**
 * References: the ANOVA estimator by its formula in numpy (run by hand), and for the balanced
 * case statsmodels' {@code mixedlm("y ~ 1", groups=sequence).fit(reml=True)}, an independent
 * likelihood fit that equals the ANOVA estimator on balanced data (statsmodels 0.15.0) when MSB &gt; MSW: it gave
 * sd_seq = 0.12246575791962687, sd_seed = 0.015345435506109551 (optimizer tolerance ~3e-6).
 */
class VarianceComponentsTest {
    private static final double TIGHT = 1e-13;
    private static final double REML_TOL = 1e-5;

    /** 8 sequences x 5 seeds: sequence effect plus 0.02 sin(7s + 3k), rounded to 6 decimals. */
    private static final double[][] BALANCED = {
        {0.1, 0.102822, 0.094412, 0.108242, 0.089269}, {0.31314, 0.28912, 0.308403, 0.294242, 0.302998},
        {0.069812, 0.030772, 0.068259, 0.033076, 0.065251}, {0.236733, 0.201888, 0.239128, 0.200239, 0.239998},
        {0.415418, 0.401919, 0.420582, 0.397129, 0.424902}, {0.171436, 0.185927, 0.176828, 0.180354, 0.182471},
        {0.25167, 0.287018, 0.254635, 0.283405, 0.258824}, {0.070925, 0.109733, 0.070005, 0.109857, 0.070678}};

    @Test
    void balancedSplitMatchesTheAnovaFormulaAndTheRemlFit() {
        VarianceComponents.Result r = VarianceComponents.of(BALANCED);
        assertEquals(8, r.sequences());
        assertEquals(40, r.values());
        assertEquals(5.0, r.seedsPerSequence(), TIGHT);
        assertEquals(0.12246615120103159, Math.sqrt(r.sequenceVariance()), TIGHT);
        assertEquals(0.015345424767255547, Math.sqrt(r.seedVariance()), TIGHT);
        assertEquals(0.9845417674928885, r.sequenceShare(), TIGHT);
        assertEquals(0.12246575791962687, Math.sqrt(r.sequenceVariance()), REML_TOL);
        assertEquals(0.015345435506109551, Math.sqrt(r.seedVariance()), REML_TOL);
        assertEquals(VarianceComponents.Advice.MORE_SEQUENCES, r.advice());
    }

    @Test
    void unbalancedGroupsUseTheEffectiveGroupSize() {
        // a sequence with one value still counts for MSB; an empty one is skipped; n0 = (10 - 30/10)/3 = 7/3
        VarianceComponents.Result r = VarianceComponents.of(new double[][] {{1.0, 1.2, 0.9}, {2.0, 2.1},
            {0.5, 0.7, 0.6, 0.4}, {1.5}, {}});
        assertEquals(4, r.sequences());
        assertEquals(7.0 / 3.0, r.seedsPerSequence(), TIGHT);
        assertEquals(0.6693813775206392, Math.sqrt(r.sequenceVariance()), TIGHT);
        assertEquals(0.13017082793177756, Math.sqrt(r.seedVariance()), TIGHT);
        assertEquals(0.9635615783724741, r.sequenceShare(), TIGHT);
    }

    @Test
    void seedNoiseLargerThanTheSequenceSpreadAdvisesMoreSeeds() {
        // identical sequence means (MSB = 0): sigma_seq = 0 by the max(0, .) rule, all variance between seeds
        VarianceComponents.Result r = VarianceComponents.of(new double[][] {{1, 3}, {3, 1}, {2, 2}});
        assertEquals(0.0, r.sequenceVariance(), 0.0);
        assertEquals(4.0 / 3.0, r.seedVariance(), TIGHT); // (1+1+1+1+0+0)/(6-3)
        assertEquals(VarianceComponents.Advice.MORE_SEEDS, r.advice());
    }

    @Test
    void notEstimableWithOneSequenceOrOneSeedEach() {
        assertNull(VarianceComponents.of(new double[][] {{1, 2, 3}}));
        assertNull(VarianceComponents.of(new double[][] {{1}, {2}, {3}}));
    }
}
