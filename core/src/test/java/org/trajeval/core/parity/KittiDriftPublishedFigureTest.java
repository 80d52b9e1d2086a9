package org.trajeval.core.parity;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.report.EvaluationReport;

/**
 * The KITTI drift of the ORB-SLAM stereo estimate of sequence 00 shipped in ../shared/refdata
 * against the published figure: Mur-Artal and Tardos, "ORB-SLAM2: an Open-Source SLAM System for
 * Monocular, Stereo and RGB-D Cameras", IEEE T-RO 2017, Table II, sequence 00: t_rel 0.70 %,
 * r_rel 0.25 deg/100 m (given to two decimals, so compared to half a unit of the last digit).
 */
class KittiDriftPublishedFigureTest {
    @Test
    void orbSlamStereoOnKitti00MatchesThePublishedDrift() {
        Path dir = EvoParityTest.refdata();
        ReadOptions kitti = ReadOptions.defaults().withFormat(TrajectoryFormat.KITTI);
        LoadedTrajectory gt = TrajectoryReader.read(dir.resolve("KITTI_00_gt.txt"), kitti);
        LoadedTrajectory orb = TrajectoryReader.read(dir.resolve("KITTI_00_ORB.txt"), kitti);
        EvaluationReport r = Evaluator.evaluate(gt, orb, EvaluationOptions.preset(Convention.KITTI));
        assertEquals(0.70, r.drift().transPct(), 0.005, "t_rel (%)");
        assertEquals(0.25, 100 * r.drift().rotDegPerM(), 0.005, "r_rel (deg/100 m)");
    }
}
