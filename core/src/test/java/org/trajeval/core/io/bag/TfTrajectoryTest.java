package org.trajeval.core.io.bag;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * TF trajectories on a generated bag whose answers are derived by hand:
 * map->odom at 10 s = (1, 0, 0), no rotation; at 12 s = (3, 0, 0), 90 deg about z.
 * odom->base_link (1, 0, 0), no rotation, at 10.5, 11, 11.5 and 13 s (the driving edge);
 * base_link->laser (0, 0, 0.5) static.
 */
class TfTrajectoryTest {
    private static final double TOL_M = 1e-12;
    private static final double S45 = Math.sin(Math.PI / 4);

    @TempDir
    Path dir;

    private static BagWriters.Pose tf(double t, String parent, String child, double x, double y, double z,
            double yawRad) {
        return new BagWriters.Pose(Math.round(t * 1e9), x, y, z, 0, 0, Math.sin(yawRad / 2), Math.cos(yawRad / 2),
                parent, child);
    }

    private Path bag(List<List<BagWriters.Pose>> tfMessages) throws IOException {
        BagWriters.Topic tf = new BagWriters.Topic("/tf", "tf2_msgs/msg/TFMessage", BagWriters.TF_MESSAGE_ROS2);
        BagWriters.Topic st = new BagWriters.Topic("/tf_static", "tf2_msgs/msg/TFMessage", BagWriters.TF_MESSAGE_ROS2);
        st.add(1, BagWriters.cdrTfMessage(List.of(tf(0, "base_link", "laser", 0, 0, 0.5, 0))));
        long log = 2;
        for (List<BagWriters.Pose> m : tfMessages) {
            tf.add(log++, BagWriters.cdrTfMessage(m));
        }
        Path p = dir.resolve("tf.mcap");
        Files.write(p, BagWriters.mcap(List.of(tf, st), "lz4", 3, true));
        return p;
    }

    private Path standardBag() throws IOException {
        return bag(List.of(List.of(tf(10, "map", "odom", 1, 0, 0, 0)),
                List.of(tf(10.5, "odom", "base_link", 1, 0, 0, 0)),
                List.of(tf(11, "odom", "base_link", 1, 0, 0, 0), tf(12, "map", "odom", 3, 0, 0, Math.PI / 2)),
                List.of(tf(11.5, "odom", "base_link", 1, 0, 0, 0)),
                List.of(tf(13, "odom", "base_link", 1, 0, 0, 0))));
    }

    private static LoadedTrajectory read(Path bag, String id) {
        return BagTrajectoryReader.read(bag, BagReadOptions.of(id), ReadOptions.defaults());
    }

    @Test
    void composedTransformIsInterpolatedAtTheDrivingEdgesStamps() throws IOException {
        SpatialTrajectory t = (SpatialTrajectory) read(standardBag(), "/tf:map.laser").trajectory();
        // stamps of odom->base_link inside map->odom's span: 10.5, 11, 11.5 (13 would need extrapolation)
        assertEquals(3, t.size());
        // at 11 s: map->odom halfway: (2, 0, 0) and 45 deg (slerp); then (1, 0, 0.5) turned by 45 deg
        assertEquals(11.0, t.t(1), 0.0);
        assertEquals(2 + S45, t.x(1), TOL_M);
        assertEquals(S45, t.y(1), TOL_M);
        assertEquals(0.5, t.z(1), TOL_M);
        assertEquals(Math.cos(Math.PI / 8), t.qw(1), TOL_M);
        assertEquals(Math.sin(Math.PI / 8), t.qz(1), TOL_M);
        // at 10.5 s: a quarter of the way: (1.5, 0, 0) and 22.5 deg
        assertEquals(1.5 + Math.cos(Math.PI / 8), t.x(0), TOL_M);
        assertEquals(Math.sin(Math.PI / 8), t.y(0), TOL_M);
    }

    @Test
    void stampsOutsideAnotherEdgesSpanAreDroppedAndCounted() throws IOException {
        LoadedTrajectory t = read(standardBag(), "/tf:map.base_link");
        assertEquals(3, t.trajectory().size());
        assertTrue(t.formatReason().contains("1 stamps dropped"), t.formatReason());
    }

    @Test
    void inverseDirectionInvertsTheComposedTransform() throws IOException {
        SpatialTrajectory t = (SpatialTrajectory) read(standardBag(), "/tf:laser.map").trajectory();
        // laser->map at 11 s = (map->laser)^-1: -R^T p with p = (2 + c, c, 0.5), c = sin 45 deg, R = 45 deg about z:
        // R^T p = (c (2 + c) + c c, -c (2 + c) + c c, 0.5) = (2c + 1, -2c, 0.5)
        assertEquals(-(2 * S45 + 1), t.x(1), TOL_M);
        assertEquals(2 * S45, t.y(1), TOL_M);
        assertEquals(-0.5, t.z(1), TOL_M);
    }

    @Test
    void repeatedStampOfAnEdgeKeepsTheFirstTransformAsTf2Does() throws IOException {
        // tf2's TimeCache refuses a second transform with a stamp it already holds
        Path bag = bag(List.of(List.of(tf(1, "map", "odom", 1, 0, 0, 0)), List.of(tf(1, "map", "odom", 9, 0, 0, 0)),
                List.of(tf(2, "map", "odom", 2, 0, 0, 0))));
        SpatialTrajectory t = (SpatialTrajectory) read(bag, "/tf:map.odom").trajectory();
        assertEquals(2, t.size());
        assertEquals(1.0, t.x(0), 0.0);
    }

    @Test
    void frameWithTwoParentsIsRefused() throws IOException {
        Path bag = bag(List.of(List.of(tf(1, "map", "odom", 0, 0, 0, 0)), List.of(tf(2, "world", "odom", 0, 0, 0, 0))));
        InputException e = assertThrows(InputException.class, () -> read(bag, "/tf:map.odom"));
        assertEquals(InputProblem.CORRUPT_BAG, e.problem());
        assertTrue(e.getMessage().contains("'odom' has two parents, 'map' and 'world'"), e.getMessage());
    }

    @Test
    void framesInDifferentTreesAreRefused() throws IOException {
        Path bag = bag(List.of(List.of(tf(1, "map", "odom", 0, 0, 0, 0), tf(1, "world", "gps", 0, 0, 0, 0))));
        InputException e = assertThrows(InputException.class, () -> read(bag, "/tf:odom.gps"));
        assertEquals(InputProblem.UNKNOWN_TOPIC, e.problem());
        assertTrue(e.getMessage().contains("different trees"), e.getMessage());
    }

    @Test
    void tfTopicReadAsAPlainTopicIsRefusedWithTheTfSyntax() throws IOException {
        Path bag = standardBag();
        InputException e = assertThrows(InputException.class, () -> read(bag, "/tf"));
        assertEquals(InputProblem.UNKNOWN_TOPIC, e.problem());
        assertTrue(e.getMessage().contains("/tf:PARENT.CHILD"), e.getMessage());
    }
}
