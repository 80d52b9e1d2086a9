package org.trajeval.core.metric;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Arrays;
import org.junit.jupiter.api.Test;
import org.trajeval.core.RefData;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.Evaluation;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.traj.PoseSequence;

/** Relative error per sub-trajectory length: hand derivations on small paths, and KITTI 00. */
class SubTrajectoryErrorsTest {
    private static final double PCT_TOL = 1e-9;
    private static final double DEG_PER_M_TOL = 1e-9;

    /** Poses on the x axis at x_k = scale k (m), k = 0..n-1, heading yaw_k = yawStep k (rad) about z. */
    private static PoseSequence line(int n, double scale, double yawStep) {
        double[] x = new double[n];
        double[] r = new double[9 * n];
        for (int k = 0; k < n; k++) {
            x[k] = scale * k;
            double c = Math.cos(yawStep * k);
            double s = Math.sin(yawStep * k);
            System.arraycopy(new double[] {c, -s, 0, s, c, 0, 0, 0, 1}, 0, r, 9 * k, 9);
        }
        return PoseSequence.of(x, new double[n], new double[n], r);
    }

    @Test
    void stretchedEstimateGivesTheStretchOverTheLengthForEverySegment() {
        // reference: 11 poses 1 m apart (10 m); estimate stretched by 10 %. L = 2 m: the end of a segment
        // from f is the first pose beyond d_f + 2 m, f + 3 (d = 3 m); the estimate moves 3.3 m, so
        // |trans(E)| = 0.3 m and 0.3 / 2 x 100 = 15 %. Starts f = 0..7 have an end (f + 3 <= 10): 8 segments.
        SubTrajectoryErrors s = SubTrajectoryErrors.compute(line(11, 1.0, 0), line(11, 1.1, 0), new double[] {2.0});
        SubTrajectoryErrors.AtLength a = s.perLength().get(0);
        assertEquals(1, s.stepFrames());
        assertEquals(8, a.size());
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5, 6, 7}, a.first());
        for (int i = 0; i < a.size(); i++) {
            assertEquals(15.0, a.transPct()[i], PCT_TOL);
            assertEquals(0.0, a.rotDegPerM()[i], DEG_PER_M_TOL);
        }
    }

    @Test
    void turningEstimateGivesItsTurnOverTheLength() {
        // estimate: the reference's positions with the heading turning 0.01 rad per pose. L = 2 m again ends
        // each segment 3 poses on: angle(E) = 0.03 rad, 0.03 rad = 1.718873 deg, / 2 m = 0.859437 deg/m.
        // Translation: E's translation is R_Pf^-1... = Rz(-0.03) ((3,0,0) - Rz(-0.01 f) (3,0,0)), of norm
        // |(3,0,0) - Rz(-0.01 f)(3,0,0)| = 2 * 3 * sin(0.01 f / 2) (chord of a 3 m radius), / 2 m x 100 %.
        SubTrajectoryErrors s = SubTrajectoryErrors.compute(line(11, 1.0, 0), line(11, 1.0, 0.01),
                new double[] {2.0});
        SubTrajectoryErrors.AtLength a = s.perLength().get(0);
        assertEquals(8, a.size());
        for (int i = 0; i < a.size(); i++) {
            assertEquals(Math.toDegrees(0.03) / 2.0, a.rotDegPerM()[i], DEG_PER_M_TOL);
            assertEquals(100.0 * 6.0 * Math.sin(0.005 * a.first()[i]) / 2.0, a.transPct()[i], PCT_TOL);
        }
    }

    @Test
    void defaultLengthsAreTenToFiftyPercentOfTheReferencePath() {
        // 101 poses 1 m apart: a 100 m path, so 10, 20, 30, 40, 50 m; a length of L m ends L + 1 poses on,
        // so 100 - L starts have a segment
        SubTrajectoryErrors s = SubTrajectoryErrors.compute(line(101, 1.0, 0), line(101, 1.0, 0), null);
        assertArrayEquals(new double[] {10, 20, 30, 40, 50},
                s.perLength().stream().mapToDouble(SubTrajectoryErrors.AtLength::lengthM).toArray(), 1e-9);
        assertArrayEquals(new int[] {90, 80, 70, 60, 50},
                s.perLength().stream().mapToInt(SubTrajectoryErrors.AtLength::size).toArray());
    }

    @Test
    void aStandingReferenceHasNoDefaultLengthsAndLongPathsStartFewerSegments() {
        assertTrue(SubTrajectoryErrors.compute(line(5, 0.0, 0), line(5, 0.0, 0), null).perLength().isEmpty());
        // 12 001 poses: a start every ceil(12001 / 5000) = 3 poses
        SubTrajectoryErrors s = SubTrajectoryErrors.compute(line(12_001, 0.01, 0), line(12_001, 0.01, 0),
                new double[] {1.0});
        assertEquals(3, s.stepFrames());
        assertEquals(0, s.perLength().get(0).first()[1] % 3);
    }

    @Test
    void onKitti00EveryLengthsMeanIsTheKittiDriftAtThatLengthAndThePooledMeanThePublishedOne() {
        // The same segments as the devkit's drift: the mean of the kept values per length is the drift of
        // that length (same search, step 1 here since 4541 poses < 5000). ORB-SLAM2's published t_rel on
        // sequence 00 (Mur-Artal and Tardos, T-RO 2017, Table II) is 0.70 % with the devkit's step of 10;
        // every start instead of every 10th moves the mean by less than 0.01 %.
        Path dir = RefData.dir();
        ReadOptions kitti = ReadOptions.defaults().withFormat(TrajectoryFormat.KITTI);
        LoadedTrajectory gt = TrajectoryReader.read(dir.resolve("KITTI_00_gt.txt"), kitti);
        LoadedTrajectory orb = TrajectoryReader.read(dir.resolve("KITTI_00_ORB.txt"), kitti);
        Evaluation e = Evaluator.run(gt, orb, EvaluationOptions.preset(Convention.KITTI));
        double[] lengths = DriftOptions.KITTI.segmentLengthsM();
        SubTrajectoryErrors s = SubTrajectoryErrors.compute(e.reference(), e.alignedEstimate(), lengths);
        DriftResult d = LengthNormalisedDrift.compute(e.reference(), e.alignedEstimate(), new DriftOptions(lengths, 1));
        assertEquals(1, s.stepFrames());
        double pooled = 0;
        int n = 0;
        for (int li = 0; li < lengths.length; li++) {
            SubTrajectoryErrors.AtLength a = s.perLength().get(li);
            assertEquals(d.perLength().get(li).segments(), a.size());
            assertEquals(d.perLength().get(li).transPct(), Arrays.stream(a.transPct()).average().orElseThrow(), 1e-9);
            assertEquals(d.perLength().get(li).rotDegPerM(), Arrays.stream(a.rotDegPerM()).average().orElseThrow(),
                    1e-12);
            pooled += Arrays.stream(a.transPct()).sum();
            n += a.size();
        }
        assertEquals(0.70, pooled / n, 0.01, "t_rel (%) over every segment");
    }
}
