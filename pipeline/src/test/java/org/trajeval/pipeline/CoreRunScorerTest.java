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

    @Test
    void contentHashFromTheReadPassEqualsTheHashOfTheFiles() throws Exception {
        // a CSV pair and a TUM pair (the two reader paths); ContentHash.of(job) reads the files for the
        // hashes as every earlier version did, so ledgers written before still recognise their runs
        Fixtures.writeTrajectory(dir.resolve("gt.csv"), 300, 0.0, 3);
        Fixtures.writeTrajectory(dir.resolve("est.csv"), 300, 0.05, 4);
        java.nio.file.Files.writeString(dir.resolve("gt.tum"), "1.0 0 0 0 0 0 0 1\n2.0 1 0 0 0 0 0 1\n3.0 2 1 0 0 0 0 1\n");
        java.nio.file.Files.writeString(dir.resolve("est.tum"), "1.0 0 0 0 0 0 0 1\n2.0 1 0.1 0 0 0 0 1\n3.0 2 1 0 0 0 0 1\n");
        CoreRunScorer scorer = new CoreRunScorer(1 << 20);
        for (String ext : new String[] {"csv", "tum"}) {
            RunJob job = new RunJob(RunMetadata.ofName("r-" + ext), dir.resolve("gt." + ext), dir.resolve("est." + ext),
                    SettingValues.DEFAULTS, "test");
            RunInputs in = scorer.read(job);
            assertEquals(org.trajeval.pipeline.bundle.ContentHash.of(job), org.trajeval.pipeline.bundle.ContentHash.of(
                    job, in.reference().sha256(), in.estimate().sha256()), ext);
            assertEquals(scorer.score(job).ate(), scorer.score(job, in).ate(), ext);
        }
    }
}
