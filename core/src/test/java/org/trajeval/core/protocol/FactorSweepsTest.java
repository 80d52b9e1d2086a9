package org.trajeval.core.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.trajeval.core.protocol.SimRealFixtures.byMethod;
import static org.trajeval.core.protocol.SimRealFixtures.failed;
import static org.trajeval.core.protocol.SimRealFixtures.ok;
import static org.trajeval.core.protocol.SimRealFixtures.seq;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;
import org.trajeval.core.report.FactorSweep;
import org.trajeval.core.report.SuiteReport.RunEntry;

class FactorSweepsTest {
    private static final double TOL = 1e-12;

    @Test
    void breakdownIsTheLowestLevelWhoseFailureRateReachesTheBreakdownRate() {
        // levels 0, 0.2, 0.4, 0.6 with 5 seeds each and 0, 1, 3, 5 failures: rates 0, 0.2, 0.6, 1.0;
        // at breakdown rate 0.5 the breakdown level is 0.4; a steady method never breaks down
        double[] levels = {0.0, 0.2, 0.4, 0.6};
        int[] failures = {0, 1, 3, 5};
        double[] ate = {0.1, 0.2, 0.3, 0.4};
        List<SequenceSpec> seqs = new ArrayList<>();
        List<RunEntry> runs = new ArrayList<>();
        for (int i = 0; i < levels.length; i++) {
            seqs.add(seq("d" + i, "sim", null, Map.of("obstacle_density", levels[i])));
            for (int seed = 1; seed <= 5; seed++) {
                runs.add(seed <= failures[i] ? failed("fragile", "d" + i, seed) : ok("fragile", "d" + i, seed, ate[i]));
            }
        }
        for (int i = 0; i < levels.length; i++) {
            for (int seed = 1; seed <= 5; seed++) {
                runs.add(ok("steady", "d" + i, seed, 0.1));
            }
        }
        List<FactorSweep> sweeps = FactorSweeps.compute(seqs, byMethod(runs), List.of("ate_trans_rmse_m"), 0.95, 0.5);
        assertEquals(1, sweeps.size());
        FactorSweep s = sweeps.get(0);
        assertEquals("obstacle_density", s.factor());
        assertEquals(List.of(0.0, 0.2, 0.4, 0.6), s.levels());
        FactorSweep.MethodSweep fragile = s.methods().get(0);
        assertEquals(0.4, fragile.breakdownLevel(), 0.0);
        assertEquals(0.6, fragile.levels().get(2).failureRate().estimate(), TOL);
        assertEquals(3, fragile.levels().get(2).failures());
        // level 0: five values 0.1: median 0.1, the whole range (n = 5 < 6), achieved level 1 - 2/32
        FactorSweep.LevelMetric m0 = fragile.levels().get(0).metrics().get(0);
        assertEquals(0.1, m0.median(), TOL);
        assertEquals(0.9375, m0.achievedLevel(), TOL);
        // all runs failed at 0.6: no value
        assertNull(fragile.levels().get(3).metrics().get(0).median());
        // sensitivity: 5 + 4 + 2 ok values, monotone in the level with the same ties: C = 5*4 + 5*2 + 4*2 = 38,
        // D = 0, n0 = 55, 17 tied pairs on each side: tau_b = 38 / sqrt(38 * 38) = 1
        assertEquals(11, fragile.sensitivity().get(0).n());
        assertEquals(1.0, fragile.sensitivity().get(0).kendallTau(), TOL);
        assertNull(s.methods().get(1).breakdownLevel());
        // a constant value has no rank correlation
        assertNull(s.methods().get(1).sensitivity().get(0).kendallTau());
    }

    @Test
    void sequencesDifferingInTwoFactorsAreNamed() {
        List<SequenceSpec> seqs = List.of(seq("s1", "sim", null, Map.of("density", 0.0, "friction", 1.0)),
                seq("s2", "sim", null, Map.of("density", 0.2, "friction", 1.0)),
                seq("s3", "sim", null, Map.of("density", 0.4, "friction", 0.5)));
        List<String> w = FactorSweeps.oneFactorAtATimeWarnings(seqs);
        assertEquals(2, w.size());
        assertTrue(w.get(0).contains("'density'") && w.get(0).contains("s1 and s3 differ in density, friction"),
                w.get(0));
        assertEquals(List.of(), FactorSweeps.oneFactorAtATimeWarnings(seqs.subList(0, 2)));
    }
}
