package org.trajeval.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.concurrent.TimeUnit;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.Warmup;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.bag.BagReadOptions;
import org.trajeval.core.io.bag.BagTrajectoryReader;
import org.trajeval.core.io.bag.BagWriters;

/**
 * Reading one pose topic out of a generated MCAP bag that also holds unrelated high-rate topics
 * (a 200 kB "image" and a 100 kB "point cloud" every 1000 poses, i.e. about 70 % of the bytes):
 * {@code poses} geometry_msgs/PoseStamped messages, chunks of 1000 messages, uncompressed or lz4.
 * The bag is written once into {@code bench/data/bags/} (git-ignored). Score: ms per read of the
 * whole topic; poses per second = poses / score * 1000.
 */
@State(Scope.Benchmark)
@BenchmarkMode(Mode.SingleShotTime)
@OutputTimeUnit(TimeUnit.MILLISECONDS)
@Fork(value = 1, jvmArgsAppend = {"-Xmx6g"})
@Warmup(iterations = 2)
@Measurement(iterations = 5)
public class BagBenchmarks {
    @Param({"1000000"})
    public int poses;

    @Param({"none", "lz4"})
    public String compression;

    private Path bag;

    @Setup
    public void writeBag() throws IOException {
        Path dir = Path.of(System.getProperty("bench.data", "data"), "bags");
        Files.createDirectories(dir);
        bag = dir.resolve("poses-" + poses + "-" + compression + ".mcap");
        if (Files.isRegularFile(bag)) {
            return;
        }
        Random r = new Random(7);
        BagWriters.Topic pose = new BagWriters.Topic("/pose", "geometry_msgs/msg/PoseStamped",
                BagWriters.POSE_STAMPED_ROS2);
        BagWriters.Topic image = new BagWriters.Topic("/camera/image_raw", "sensor_msgs/msg/Image", "uint8[] data\n");
        BagWriters.Topic cloud = new BagWriters.Topic("/lidar/points", "sensor_msgs/msg/PointCloud2",
                "uint8[] data\n");
        byte[] pixels = new byte[200_000];
        byte[] points = new byte[100_000];
        for (int i = 0; i < poses; i++) {
            long t = 1_700_000_000_000_000_000L + i * 5_000_000L;
            double yaw = 0.001 * i;
            pose.add(t, BagWriters.cdrPoseStamped(BagWriters.Pose.of(t, 0.01 * i, Math.sin(yaw), 0, 0, 0,
                    Math.sin(yaw / 2), Math.cos(yaw / 2))));
            if (i % 1000 == 500) {
                r.nextBytes(pixels);
                for (int k = 0; k < pixels.length; k += 2) {
                    pixels[k] = 0; // half the bytes constant: an image compresses a little
                }
                image.add(t + 1, pixels.clone());
                r.nextBytes(points);
                cloud.add(t + 2, points.clone());
            }
        }
        List<BagWriters.Topic> topics = new ArrayList<>(List.of(pose, image, cloud));
        Files.write(bag, BagWriters.mcap(topics, compression.equals("none") ? "" : compression, 1000, true));
    }

    @Benchmark
    public int readPoseTopic() {
        LoadedTrajectory t = BagTrajectoryReader.read(bag, BagReadOptions.of("/pose"), ReadOptions.defaults());
        return t.trajectory().size();
    }
}
