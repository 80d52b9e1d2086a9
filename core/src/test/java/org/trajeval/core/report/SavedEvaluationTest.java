package org.trajeval.core.report;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.zip.GZIPOutputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.Evaluation;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.traj.PlanarTrajectory;

/** Saved per-pose series: what is written reads back bit for bit, and a damaged file is refused by name and line. */
class SavedEvaluationTest {
    @TempDir
    Path dir;

    /** 50 poses at 10 Hz from t = 1000 s on a line; the estimate 0.10 m to the left of the truth. */
    static Evaluation offsetPair() {
        int n = 50;
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] ey = new double[n];
        double[] yaw = new double[n];
        for (int k = 0; k < n; k++) {
            t[k] = 1000.0 + 0.1 * k;
            x[k] = 0.5 * k;
            ey[k] = 0.10;
        }
        LoadedTrajectory ref = new LoadedTrajectory("ref.csv", TrajectoryFormat.CSV, "given",
                PlanarTrajectory.of(t, x, y, yaw), null, false);
        LoadedTrajectory est = new LoadedTrajectory("est.csv", TrajectoryFormat.CSV, "given",
                PlanarTrajectory.of(t.clone(), x.clone(), ey, yaw.clone()), null, false);
        return Evaluator.run(ref, est, EvaluationOptions.preset(Convention.LESSON, true)
                .withAlignment(AlignmentModel.NONE));
    }

    @Test
    void seriesStartAtZeroSecondsAndHoldThePerPoseErrors() {
        EvaluationSeries s = EvaluationSeries.of(offsetPair(), false);
        assertEquals("s", s.timeUnit());
        assertEquals(0.0, s.poses().t()[0]);
        assertEquals(4.9, s.poses().t()[49], 1e-9); // 49 steps of 0.1 s after 1000 s
        for (double e : s.poses().ateTransM()) {
            assertEquals(0.10, e, 1e-12); // every pose 0.10 m off, nothing aligned: ATE = 0.10 m by hand
        }
        assertEquals(s.pairs().size(), s.pairs().rpeTransM().length);
    }

    @Test
    void writtenFolderReadsBackBitForBit() {
        Evaluation e = offsetPair();
        SavedEvaluation saved = new SavedEvaluation(e.report(), EvaluationSeries.of(e, false));
        saved.write(dir);
        SavedEvaluation back = SavedEvaluation.read(dir);
        assertArrayEquals(saved.series().poses().t(), back.series().poses().t());
        assertArrayEquals(saved.series().poses().estY(), back.series().poses().estY());
        assertArrayEquals(saved.series().poses().ateTransM(), back.series().poses().ateTransM());
        assertArrayEquals(saved.series().pairs().rpeRotRad(), back.series().pairs().rpeRotRad());
        assertEquals(saved.report().ate().transM(), back.report().ate().transM());
        EvaluationSeries.Segments g = saved.series().segments();
        assertTrue(g.size() > 0);
        assertArrayEquals(g.lengthM(), back.series().segments().lengthM());
        assertArrayEquals(g.t(), back.series().segments().t());
        assertArrayEquals(g.transPct(), back.series().segments().transPct());
        assertArrayEquals(g.rotDegPerM(), back.series().segments().rotDegPerM());
    }

    @Test
    void segmentsAreTheSubTrajectoryErrorsOfTheEvaluationAtTheirStartTimes() {
        // the path runs 24.5 m along x (49 steps of 0.5 m); default lengths 10 ... 50 %: 2.45, 4.9, ... 12.25 m.
        // The estimate is the reference shifted sideways (no alignment): every relative motion is the same,
        // so every segment's error is 0 and a length of L m ends at the first pose beyond L.
        EvaluationSeries s = EvaluationSeries.of(offsetPair(), false);
        EvaluationSeries.Segments g = s.segments();
        assertArrayEquals(new double[] {2.45, 4.9, 7.35, 9.8, 12.25}, g.lengths(), 1e-9);
        // 2.45 m ends 5 poses on (2.5 m): starts 0..44, i.e. 45 segments, the first at t = 0 s, the last at 4.4 s
        double[] t = g.at(g.t(), g.lengths()[0]);
        assertEquals(45, t.length);
        assertEquals(4.4, t[44], 1e-9);
        for (double v : g.transPct()) {
            assertEquals(0.0, v, 1e-9);
        }
    }

    @Test
    void aFolderSavedBeforeSegmentsReadsWithNone() throws Exception {
        Evaluation e = offsetPair();
        new SavedEvaluation(e.report(), EvaluationSeries.of(e, false)).write(dir);
        Files.delete(dir.resolve(SavedEvaluation.SEGMENTS));
        assertEquals(0, SavedEvaluation.read(dir).series().segments().size());
    }

    @Test
    void aDamagedTableIsRefusedWithFileLineAndColumn() throws Exception {
        Evaluation e = offsetPair();
        new SavedEvaluation(e.report(), EvaluationSeries.of(e, false)).write(dir);
        ByteArrayOutputStream b = new ByteArrayOutputStream();
        try (GZIPOutputStream z = new GZIPOutputStream(b)) {
            z.write(("t_s,ref_x_m,ref_y_m,ref_z_m,est_x_m,est_y_m,est_z_m,ate_trans_m,ate_rot_rad\n"
                    + "0,0,0,0,0,0,0,0,0\n0,0,0,0,0,0,0,x,0\n").getBytes(StandardCharsets.UTF_8));
        }
        Files.write(dir.resolve(SavedEvaluation.POSES), b.toByteArray());
        org.trajeval.core.InputException ex = assertThrows(org.trajeval.core.InputException.class,
                () -> SavedEvaluation.read(dir));
        assertTrue(ex.getMessage().endsWith("poses.csv.gz:3: column 'ate_trans_m' must be a number, found \"x\""),
                ex.getMessage());
    }
}
