package org.trajeval.core.parity;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.trajeval.core.RefData;
import org.trajeval.core.report.EvaluationReport;

/** Units as the data has them: frames for index-stamped KITTI, KITTI's deg/100 m, and why drift is empty. */
class HonestUnitsTest {

    private static EvaluationReport evaluate(Path ref, Path est, String... kv) {
        return org.trajeval.core.eval.AlignmentWarningsTest.evaluate(ref, est, kv);
    }

    @Test
    void kittiWithoutTimesFilesCountsFrames() {
        Path d = RefData.dir();
        EvaluationReport r = evaluate(d.resolve("KITTI_00_gt.txt"), d.resolve("KITTI_00_ORB.txt"),
                "convention", "kitti");
        assertEquals("frames", r.timeBase());
        assertEquals("frames", r.rpe().unit());
        // ORB-SLAM2 stereo on KITTI 00: 0.25 deg/100 m (Mur-Artal and Tardos, T-RO 2017, Table II)
        assertEquals(0.25, r.drift().rotDegPer100m(), 0.005);
        assertEquals(Math.toRadians(r.drift().rotDegPerM()), r.drift().rotRadPerM(), 1e-15);
        EvaluationReport timed = evaluate(d.resolve("KITTI_00_gt.txt"), d.resolve("KITTI_00_ORB.txt"),
                "convention", "kitti", "ref_times", d.resolve("KITTI_00_gt_times.txt").toString(), "est_times",
                d.resolve("KITTI_00_gt_times.txt").toString());
        assertEquals("s", timed.timeBase());
    }

    @Test
    void driftOnAShortPathSaysWhyItIsEmpty() {
        Path d = RefData.dir();
        // freiburg1_xyz moves a few metres in all: no 100 m segment fits
        EvaluationReport r = evaluate(d.resolve("freiburg1_xyz-groundtruth.txt"),
                d.resolve("freiburg1_xyz-rgbdslam.txt"), "drift", "true");
        assertEquals(0, r.drift().segments());
        assertTrue(r.drift().pathLengthM() < 100.0, "path " + r.drift().pathLengthM());
        assertTrue(r.warnings().stream().anyMatch(w -> w.code().equals("drift_path_too_short")
                && w.message().contains("shorter than the shortest segment length")), r.warnings().toString());
    }
}
