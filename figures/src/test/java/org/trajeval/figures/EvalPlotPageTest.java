package org.trajeval.figures;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.trajeval.core.report.EvaluationReport;

/** The numbers above the eval plot page's figures: coverage, the longest gap and the warnings. */
class EvalPlotPageTest {
    @Test
    void coverageLongestGapAndEveryWarningAreListedAndEscaped() {
        EvaluationReport base = EvalFiguresTest.kittiLikeDrive(100, "se3", false).report();
        // 90 % of a 120 s span covered; the longest stretch without an estimate pose 8 s from 1300 s
        EvaluationReport r = new EvaluationReport(base.schema(), base.schemaVersion(), base.version(),
                base.convention(), base.inputs(), base.association(), base.alignment(), base.ate(), base.rpe(),
                base.drift(), new EvaluationReport.CoverageInfo(0.9, 8.0, 1300.0, 12.0, 120.0), base.warnings(), "s",
                base.extra())
                .withWarning(new EvaluationReport.Warning("poses_dropped_in_reference_gaps", "3 poses <dropped>"))
                .withWarning(new EvaluationReport.Warning("n_to_align_clamped", "clamped"));
        String h = EvalPlotPage.numbers(r);
        assertTrue(h.contains("coverage 90.0 % of the reference's 120 s; longest stretch without an estimate pose "
                + "8 s from 1300 s (reference clock); 12 s uncovered in all."), h);
        assertTrue(h.contains("<li><code>poses_dropped_in_reference_gaps</code>: 3 poses &lt;dropped&gt;</li>"), h);
        assertTrue(h.contains("<li><code>n_to_align_clamped</code>: clamped</li>"), h);
    }

    @Test
    void aReportWithoutCoverageOrWarningsListsNeither() {
        String h = EvalPlotPage.numbers(EvalFiguresTest.kittiLikeDrive(100, "se3", false).report());
        assertFalse(h.contains("coverage"), h);
        assertFalse(h.contains("Warnings"), h);
    }
}
