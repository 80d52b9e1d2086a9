package org.trajeval.pipeline;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.SettingText;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.report.EvaluationReport;

class CoreRunScorerTest {
    /** Identical files: every error is exactly 0 up to rounding of the alignment (m). */
    private static final double ZERO_TOL_M = 1e-9;

    @TempDir
    Path dir;

    @Test
    void identicalTrajectoriesScoreZeroAteWithTheRealEngine() {
        Fixtures.writeTrajectory(dir.resolve("gt.csv"), 200, 0.0, 1);
        Fixtures.writeTrajectory(dir.resolve("est.csv"), 200, 0.0, 1);
        EvaluationReport r = new CoreRunScorer(1 << 20).score(new RunJob(RunMetadata.ofName("r"), dir.resolve("gt.csv"),
                dir.resolve("est.csv"), SettingValues.DEFAULTS, "test"));
        assertEquals(0.0, r.ate().transM().rmse(), ZERO_TOL_M);
        assertEquals("lesson", r.convention());
        assertEquals(200, r.inputs().reference().poses());
    }

    @Test
    void runSettingsOverrideTheConventionPreset() {
        SettingValues s = SettingValues.of(List.of(new SettingText("convention", "evo", "metrics.convention"),
                new SettingText("alignment", "se2", "metrics.alignment"),
                new SettingText("max_diff_s", "0.02", "metrics.max_diff_s"),
                new SettingText("rpe_delta", "5", "metrics.rpe_delta"),
                new SettingText("rpe_unit", "frames", "metrics.rpe_unit")), "run.yaml");
        var o = SettingsResolver.evaluationOptions(s, DataKind.PLANAR);
        assertEquals(org.trajeval.core.align.AlignmentModel.SE2, o.alignment());
        assertEquals(0.02, o.maxDiffS());
        assertEquals(5.0, o.rpeDelta());
        assertEquals(org.trajeval.core.metric.RpeUnit.FRAMES, o.rpeUnit());
    }

    @Test
    void unknownSettingIsRefusedNamingTheField() {
        InputException e = assertThrows(InputException.class, () -> SettingValues.of(
                List.of(new SettingText("alignment", "se4", "metrics.alignment")), "run.yaml"));
        assertEquals("metrics.alignment", e.column());
        assertEquals(InputProblem.INVALID_CONFIGURATION, e.problem());
    }
}
