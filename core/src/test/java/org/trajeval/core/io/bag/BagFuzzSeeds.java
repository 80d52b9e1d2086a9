package org.trajeval.core.io.bag;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Writes the seed corpus of {@link BagFuzzTest} (run once by hand, output committed):
 * {@code java -cp <test classpath> org.trajeval.core.io.bag.BagFuzzSeeds src/test/resources/org/trajeval/core/io/bag/BagFuzzTestInputs}.
 * Small bags of every container and compression, with a pose topic and a TF tree.
 */
public final class BagFuzzSeeds {
    private BagFuzzSeeds() {
    }

    public static void main(String[] args) throws IOException {
        Path root = Path.of(args[0]);
        List<BagWriters.Pose> poses = GeneratedBagsTest.poses(6, 5);
        BagWriters.Topic pose = new BagWriters.Topic("/pose", "geometry_msgs/msg/PoseStamped", BagWriters.POSE_STAMPED_ROS2);
        BagWriters.Topic tf = new BagWriters.Topic("/tf", "tf2_msgs/msg/TFMessage", BagWriters.TF_MESSAGE_ROS2);
        BagWriters.Topic ros1 = new BagWriters.Topic("/pose", "geometry_msgs/PoseStamped", BagWriters.POSE_STAMPED_ROS1);
        for (int i = 0; i < poses.size(); i++) {
            BagWriters.Pose p = poses.get(i);
            pose.add(p.stampNs(), BagWriters.cdrPoseStamped(p));
            tf.add(p.stampNs(), BagWriters.cdrTfMessage(List.of(
                    new BagWriters.Pose(p.stampNs(), p.x(), p.y(), 0, 0, 0, 0, 1, "map", "odom"),
                    new BagWriters.Pose(p.stampNs(), 1, 0, 0, p.qx(), p.qy(), p.qz(), p.qw(), "odom", "base_link"))));
            ros1.add(p.stampNs(), BagWriters.ros1PoseStamped(p, i));
        }
        write(root.resolve("mcap/none-summary.mcap"), BagWriters.mcap(List.of(pose, tf), "", 4, true));
        write(root.resolve("mcap/lz4-summary.mcap"), BagWriters.mcap(List.of(pose, tf), "lz4", 4, true));
        write(root.resolve("mcap/zstd-nosummary.mcap"), BagWriters.mcap(List.of(pose, tf), "zstd", 4, false));
        write(root.resolve("ros1/none.bag"), BagWriters.ros1Bag(List.of(ros1), "none", 3));
        write(root.resolve("ros1/bz2.bag"), BagWriters.ros1Bag(List.of(ros1), "bz2", 3));
        write(root.resolve("ros1/lz4.bag"), BagWriters.ros1Bag(List.of(ros1), "lz4", 3));
        // cdr: FuzzedDataProvider reads its choices from the end of the input; the plain message is a fine seed
        write(root.resolve("cdr/pose-stamped.bin"), BagWriters.cdrPoseStamped(poses.get(0)));
        write(root.resolve("cdr/tf-message.bin"), BagWriters.cdrTfMessage(List.of(poses.get(1))));
    }

    private static void write(Path p, byte[] b) throws IOException {
        Files.createDirectories(p.getParent());
        Files.write(p, b);
    }
}
