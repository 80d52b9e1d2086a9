package org.trajeval.core.io.bag;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Bags written by {@link BagWriters} with known poses (seeded) read back exactly: every container
 * and compression, with and without an MCAP summary, several chunks, an unrelated topic beside the
 * pose topic. The values are the ones written, so the expected result is the input itself.
 */
class GeneratedBagsTest {
    @TempDir
    Path dir;

    static List<BagWriters.Pose> poses(int n, long seed) {
        Random r = new Random(seed);
        List<BagWriters.Pose> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            double a = r.nextGaussian();
            double b = r.nextGaussian();
            double c = r.nextGaussian();
            double d = r.nextGaussian();
            double norm = Math.sqrt(a * a + b * b + c * c + d * d);
            out.add(BagWriters.Pose.of(1_700_000_000_000_000_000L + i * 33_333_333L + r.nextInt(1000),
                    100 * r.nextGaussian(), 100 * r.nextGaussian(), r.nextGaussian(), a / norm, b / norm, c / norm,
                    d / norm));
        }
        return out;
    }

    @ParameterizedTest(name = "MCAP, {0} chunks, summary {1}")
    @CsvSource({"none, true", "lz4, true", "zstd, true", "lz4, false", "none, false"})
    void mcapPoseStampedTopicReadsBackExactly(String compression, boolean summary) throws IOException {
        List<BagWriters.Pose> poses = poses(500, 11);
        BagWriters.Topic pose = new BagWriters.Topic("/pose", "geometry_msgs/msg/PoseStamped",
                BagWriters.POSE_STAMPED_ROS2);
        BagWriters.Topic other = new BagWriters.Topic("/camera/image", "sensor_msgs/msg/Image", "uint8[] data\n");
        for (BagWriters.Pose p : poses) {
            pose.add(p.stampNs() + 5_000_000L, BagWriters.cdrPoseStamped(p));
            other.add(p.stampNs() + 7_000_000L, new byte[] {0, 1, 0, 0, 3, 0, 0, 0, 9, 9, 9});
        }
        Path bag = dir.resolve("poses.mcap");
        Files.write(bag, BagWriters.mcap(List.of(pose, other), compression.equals("none") ? "" : compression, 64,
                summary));
        assertPoses(poses, BagTrajectoryReader.read(bag, BagReadOptions.of("/pose"), ReadOptions.defaults()));
    }

    @ParameterizedTest(name = "ROS 1 bag, {0} chunks")
    @CsvSource({"none", "bz2", "lz4"})
    void ros1PoseStampedTopicReadsBackExactly(String compression) throws IOException {
        List<BagWriters.Pose> poses = poses(400, 12);
        BagWriters.Topic pose = new BagWriters.Topic("/pose", "geometry_msgs/PoseStamped", BagWriters.POSE_STAMPED_ROS1);
        for (int i = 0; i < poses.size(); i++) {
            pose.add(poses.get(i).stampNs(), BagWriters.ros1PoseStamped(poses.get(i), i));
        }
        Path bag = dir.resolve("poses.bag");
        Files.write(bag, BagWriters.ros1Bag(List.of(pose), compression, 50));
        assertPoses(poses, BagTrajectoryReader.read(bag, BagReadOptions.of("/pose"), ReadOptions.defaults()));
    }

    @ParameterizedTest(name = "stamps from {0}")
    @CsvSource({"HEADER", "LOG_TIME"})
    void stampsComeFromTheHeaderUnlessLogTimesAreAsked(StampSource stamps) throws IOException {
        List<BagWriters.Pose> poses = poses(20, 13);
        BagWriters.Topic pose = new BagWriters.Topic("/pose", "geometry_msgs/msg/PoseStamped",
                BagWriters.POSE_STAMPED_ROS2);
        for (BagWriters.Pose p : poses) {
            pose.add(p.stampNs() + 250_000_000L, BagWriters.cdrPoseStamped(p)); // logged 0.25 s after the stamp
        }
        Path bag = dir.resolve("stamps.mcap");
        Files.write(bag, BagWriters.mcap(List.of(pose), "", 8, true));
        LoadedTrajectory t = BagTrajectoryReader.read(bag,
                new BagReadOptions("/pose", stamps, null, BagLimits.DEFAULT), ReadOptions.defaults());
        for (int i = 0; i < poses.size(); i++) {
            long ns = poses.get(i).stampNs() + (stamps == StampSource.LOG_TIME ? 250_000_000L : 0);
            // header: sec + nanosec * 1e-9 as evo computes it; log: ns / 1e9
            double expected = stamps == StampSource.LOG_TIME ? ns / 1e9
                    : Math.floorDiv(ns, 1_000_000_000L) + Math.floorMod(ns, 1_000_000_000L) * 1e-9;
            assertEquals(expected, t.trajectory().t(i), 0.0, "stamp " + i);
        }
    }

    static void assertPoses(List<BagWriters.Pose> expected, LoadedTrajectory read) {
        SpatialTrajectory t = (SpatialTrajectory) read.trajectory();
        assertEquals(expected.size(), t.size(), "poses");
        for (int i = 0; i < t.size(); i++) {
            BagWriters.Pose p = expected.get(i);
            double stamp = p.stampNs() / 1_000_000_000L + (p.stampNs() % 1_000_000_000L) * 1e-9;
            assertEquals(stamp, t.t(i), 0.0, "t " + i);
            assertEquals(p.x(), t.x(i), 0.0, "x " + i);
            assertEquals(p.y(), t.y(i), 0.0, "y " + i);
            assertEquals(p.z(), t.z(i), 0.0, "z " + i);
            assertEquals(p.qw(), t.qw(i), 0.0, "qw " + i);
            assertEquals(p.qx(), t.qx(i), 0.0, "qx " + i);
            assertEquals(p.qy(), t.qy(i), 0.0, "qy " + i);
            assertEquals(p.qz(), t.qz(i), 0.0, "qz " + i);
        }
    }
}
