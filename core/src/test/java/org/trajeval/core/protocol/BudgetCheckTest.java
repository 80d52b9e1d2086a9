package org.trajeval.core.protocol;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.trajeval.core.protocol.SimRealFixtures.ok;

import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.report.BudgetReport;
import org.trajeval.core.report.SuiteReport.RunEntry;

class BudgetCheckTest {
    private static final double TOL = 1e-12;
    private static final String HEADER = "method,sequence,seed,wall_time_s,peak_memory_mib,device\n";

    private static SuiteManifest manifest(FailureDefinition.BudgetPolicy policy) {
        return new SuiteManifest("b", List.of(SimRealFixtures.seq("a", null, null, Map.of())),
                List.of(new MethodSpec("m", "{sequence}{seed}.csv", List.of(1L, 2L, 3L, 4L), List.of())),
                List.of(1L, 2L, 3L, 4L), List.of(Split.TEST), SettingValues.of(List.of(), "x"),
                new FailureDefinition(null, null, null, policy, 0.5),
                new NormalisedScore(List.of(new NormalisedScore.Term(RunMetric.ATE_TRANS_RMSE_M, 1.0, 1.0))),
                new Budget("cpu", null, 1.0, 1024), "resources.csv");
    }

    private static final List<RunEntry> RUNS = List.of(ok("m", "a", 1, 0.1), ok("m", "a", 2, 0.1),
            ok("m", "a", 3, 0.1), ok("m", "a", 4, 0.1));

    private static ResourcesTable table() {
        // seed 1: 240 s for 60 s of data: rtf 0.25 < 1.0; seed 2: 2048 MiB > 1024; seed 3: exactly real time,
        // 100 MiB, within; seed 4: no row
        return ResourcesTable.parse(HEADER + "m,a,1,240,100,cpu\nm,a,2,30,2048,\nm,a,3,60,100,cpu\n", "r.csv",
                Set.of("m"), Set.of("a"));
    }

    @Test
    void slowAndLargeRunsAreOverTheBudgetAndFailWithTheFigureAndTheLimit() {
        BudgetCheck.Applied a = BudgetCheck.apply(manifest(FailureDefinition.BudgetPolicy.FAIL), table(), RUNS,
                Map.of("a", 60.0));
        List<BudgetReport.RunBudget> v = a.report().runs();
        assertEquals(List.of("over", "over", "within", "unknown"), v.stream().map(BudgetReport.RunBudget::status)
                .toList());
        assertEquals(0.25, v.get(0).realTimeFactor(), TOL);
        assertTrue(v.get(0).violations().get(0).contains("real-time factor 0.25 below the budget's real_time_factor"
                + " 1.0"), v.get(0).violations().toString());
        assertTrue(v.get(1).violations().get(0).contains("peak memory 2048 MiB above the budget's memory_cap_mib "
                + "1024"), v.get(1).violations().toString());
        assertEquals("budget", a.runs().get(0).failure().reason());
        assertEquals(0.0, a.runs().get(0).score(), 0.0);
        assertEquals("ok", a.runs().get(2).status());
        assertEquals(1, a.report().unknownRuns());
        BudgetReport.MethodBudget m = a.report().methods().get(0);
        // compliance = within / known = 1 / 3
        assertEquals(1.0 / 3.0, m.compliance(), TOL);
        assertEquals(1, m.unknown());
    }

    @Test
    void withWarnTheRunsKeepTheirStatusAndAWarningNamesThem() {
        BudgetCheck.Applied a = BudgetCheck.apply(manifest(FailureDefinition.BudgetPolicy.WARN), table(), RUNS,
                Map.of("a", 60.0));
        assertTrue(a.runs().stream().allMatch(RunEntry::ok));
        assertTrue(a.warnings().get(0).startsWith("BUDGET: 2 run(s) over the budget (kept, failure.budget: warn)"),
                a.warnings().get(0));
    }

    @Test
    void badResourcesRowsAreRefusedWithLineAndColumn() {
        InputException e = assertThrows(InputException.class, () -> ResourcesTable.parse(HEADER
                + "m,a,1,240,100,cpu\nother,a,1,1,1,cpu\n", "r.csv", Set.of("m"), Set.of("a")));
        assertEquals(3, e.line());
        assertEquals("method", e.column());
        e = assertThrows(InputException.class, () -> ResourcesTable.parse(HEADER + "m,a,1,0,100,cpu\n", "r.csv",
                Set.of("m"), Set.of("a")));
        assertEquals("wall_time_s", e.column());
        assertEquals(InputProblem.OUT_OF_RANGE, e.problem());
        e = assertThrows(InputException.class, () -> ResourcesTable.parse(HEADER + "m,a,1,5,1,cpu\nm,a,1,6,1,cpu\n",
                "r.csv", Set.of("m"), Set.of("a")));
        assertTrue(e.getMessage().contains("listed twice (lines 2 and 3)"), e.getMessage());
        e = assertThrows(InputException.class, () -> ResourcesTable.parse("method,sequence,seed,wall_time_s\n",
                "r.csv", Set.of("m"), Set.of("a")));
        assertEquals(InputProblem.MISSING_COLUMN, e.problem());
        e = assertThrows(InputException.class, () -> ResourcesTable.parse(HEADER.trim() + ",gpu_hours\n", "r.csv",
                Set.of("m"), Set.of("a")));
        assertEquals("gpu_hours", e.column());
        e = assertThrows(InputException.class, () -> ResourcesTable.parse(HEADER + "m,a,1,nan,1,cpu\n", "r.csv",
                Set.of("m"), Set.of("a")));
        assertEquals(InputProblem.NOT_A_NUMBER, e.problem());
    }
}
