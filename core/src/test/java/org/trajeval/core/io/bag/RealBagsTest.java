package org.trajeval.core.io.bag;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/**
 * The recordings of ../shared/refdata/ros read through every container: the facts their README
 * states (message counts, the TF edge odom->base_link equal to /odom, the ROS 1 and rosbag2
 * copies of tf_example holding the same transforms).
 */
class RealBagsTest {
    private static final ReadOptions KEEP = ReadOptions.defaults().withDuplicates(DuplicateTimestamps.KEEP);

    private static LoadedTrajectory read(String file, String topic) {
        return BagTrajectoryReader.read(BagEvoParityTest.rosData().resolve(file), BagReadOptions.of(topic), KEEP);
    }

    @Test
    void mcapTopicsHoldTheMessageCountsOfTheReadme() {
        // README of refdata/ros: /odom 2639 Odometry messages, /amcl_pose 135
        assertEquals(2639, read("nav2_turtlebot.mcap", "/odom").trajectory().size());
        assertEquals(135, read("nav2_turtlebot.mcap", "/amcl_pose").trajectory().size());
    }

    @Test
    void tfEdgeOdomToBaseLinkEqualsTheOdomTopicBitForBit() {
        // README of refdata/ros: the /tf edge odom->base_link is bit-identical to /odom
        Trajectory odom = read("nav2_turtlebot.mcap", "/odom").trajectory();
        Trajectory tf = read("nav2_turtlebot.mcap", "/tf:odom.base_link").trajectory();
        assertSame(odom, tf);
    }

    @Test
    void tfComposedMapToBaseLinkIsReadWithoutRos() {
        LoadedTrajectory t = read("nav2_turtlebot.mcap", "/tf:map.base_link");
        // driven by odom->base_link (the dynamic edge nearest the child); map->odom from AMCL starts later,
        // so the poses before its first stamp are dropped, never extrapolated
        int odom = read("nav2_turtlebot.mcap", "/odom").trajectory().size();
        assertTrue(t.trajectory().size() > 100 && t.trajectory().size() < odom, "poses: " + t.trajectory().size());
        assertTrue(t.formatReason().contains("dropped"), t.formatReason());
    }

    @Test
    void ros1AndRosbag2CopiesOfTfExampleGiveIdenticalTrajectories() {
        // README of refdata/ros: tf_example.bag (ROS 1, lz4 chunks) and tf_example/ (rosbag2 sqlite3) hold the same /tf
        Trajectory ros1 = read("tf_example.bag", "/tf:odom.base_link").trajectory();
        Trajectory ros2 = read("tf_example", "/tf:odom.base_link").trajectory();
        assertEquals(517, ros1.size(), "one pose per /tf message (odom->base_footprint), base_link static below it");
        assertSame(ros1, ros2);
    }

    @Test
    void ros1TopicsOfKittiExampleHoldTheReadmeCounts() {
        // README of refdata/ros: groundtruth 12765, ORB-SLAM 8362, S-PTAM 5439 PoseStamped messages
        assertEquals(12765, read("ROS_example.bag", "groundtruth").trajectory().size());
        assertEquals(8362, read("ROS_example.bag", "ORB-SLAM").trajectory().size());
        assertEquals(5439, read("ROS_example.bag", "S-PTAM").trajectory().size());
    }

    @Test
    void unknownTopicIsRefusedListingTheTopicsThereAre() {
        InputException e = assertThrows(InputException.class, () -> read("nav2_turtlebot.mcap", "/odometry"));
        assertEquals(InputProblem.UNKNOWN_TOPIC, e.problem());
        assertTrue(e.getMessage().contains("/amcl_pose (geometry_msgs/msg/PoseWithCovarianceStamped)"), e.getMessage());
    }

    @Test
    void unknownTfFrameIsRefusedListingTheFrames() {
        InputException e = assertThrows(InputException.class, () -> read("nav2_turtlebot.mcap", "/tf:map.wheel"));
        assertEquals(InputProblem.UNKNOWN_TOPIC, e.problem());
        assertTrue(e.getMessage().contains("'wheel' does not exist") && e.getMessage().contains("base_link"),
                e.getMessage());
    }

    static void assertSame(Trajectory a, Trajectory b) {
        assertEquals(a.size(), b.size(), "poses");
        for (int i = 0; i < a.size(); i++) {
            assertEquals(a.t(i), b.t(i), 0.0, "t " + i);
            assertEquals(a.x(i), b.x(i), 0.0, "x " + i);
            assertEquals(a.y(i), b.y(i), 0.0, "y " + i);
            assertEquals(a.z(i), b.z(i), 0.0, "z " + i);
            SpatialTrajectory sa = (SpatialTrajectory) a;
            SpatialTrajectory sb = (SpatialTrajectory) b;
            assertEquals(sa.qw(i), sb.qw(i), 0.0, "qw " + i);
            assertEquals(sa.qx(i), sb.qx(i), 0.0, "qx " + i);
            assertEquals(sa.qy(i), sb.qy(i), 0.0, "qy " + i);
            assertEquals(sa.qz(i), sb.qz(i), 0.0, "qz " + i);
        }
    }
}
