package org.trajeval.core.io.bag;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;

/**
 * Bad bags are refused with one line naming the file and what is wrong (InputException, exit 2 in
 * the CLI), never with another exception and never by reading past the file's end.
 */
class BadBagInputTest {
    @TempDir
    Path dir;

    private static final List<BagWriters.Pose> POSES = GeneratedBagsTest.poses(40, 21);

    private static BagWriters.Topic poseTopic() {
        BagWriters.Topic t = new BagWriters.Topic("/pose", "geometry_msgs/msg/PoseStamped", BagWriters.POSE_STAMPED_ROS2);
        for (BagWriters.Pose p : POSES) {
            t.add(p.stampNs(), BagWriters.cdrPoseStamped(p));
        }
        return t;
    }

    private InputException refused(byte[] bytes, String name, String topic) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, bytes);
        InputException e = assertThrows(InputException.class,
                () -> BagTrajectoryReader.read(p, BagReadOptions.of(topic), ReadOptions.defaults()));
        assertFalse(e.getMessage().contains("\n"), "one line: " + e.getMessage());
        assertTrue(e.getMessage().startsWith(p.toString()), "names the file: " + e.getMessage());
        return e;
    }

    @Test
    void everyTruncationOfAnMcapIsRefusedOrReadsEveryPose() throws IOException {
        byte[] whole = BagWriters.mcap(List.of(poseTopic()), "lz4", 7, true);
        Path p = dir.resolve("cut.mcap");
        int refusals = 0;
        for (int n = 0; n < whole.length; n += 13) {
            Files.write(p, Arrays.copyOf(whole, n));
            try {
                LoadedTrajectory t = BagTrajectoryReader.read(p, BagReadOptions.of("/pose"), ReadOptions.defaults());
                assertEquals(POSES.size(), t.trajectory().size(), "a cut at " + n + " read without refusal");
            } catch (InputException e) {
                refusals++;
            }
        }
        assertTrue(refusals > whole.length / 13 / 2, "most cuts lose data and are refused: " + refusals);
    }

    @Test
    void everyTruncationOfARos1BagIsRefusedOrReadsEveryPose() throws IOException {
        BagWriters.Topic t = new BagWriters.Topic("/pose", "geometry_msgs/PoseStamped", BagWriters.POSE_STAMPED_ROS1);
        for (int i = 0; i < POSES.size(); i++) {
            t.add(POSES.get(i).stampNs(), BagWriters.ros1PoseStamped(POSES.get(i), i));
        }
        byte[] whole = BagWriters.ros1Bag(List.of(t), "bz2", 9);
        Path p = dir.resolve("cut.bag");
        for (int n = 0; n < whole.length; n += 97) {
            Files.write(p, Arrays.copyOf(whole, n));
            try {
                LoadedTrajectory r = BagTrajectoryReader.read(p, BagReadOptions.of("/pose"), ReadOptions.defaults());
                assertEquals(POSES.size(), r.trajectory().size(), "a cut at " + n + " read without refusal");
            } catch (InputException e) {
                assertFalse(e.getMessage().contains("\n"), e.getMessage());
            }
        }
    }

    @Test
    void chunkWithABadCrcIsRefused() throws IOException {
        byte[] b = BagWriters.mcap(List.of(poseTopic()), "", 100, true);
        // flip one byte of the last pose's quaternion inside the (uncompressed) chunk
        int at = lastIndexOf(b, BagWriters.cdrPoseStamped(POSES.get(POSES.size() - 1))) + 60;
        b[at] ^= 0x10;
        InputException e = refused(b, "crc.mcap", "/pose");
        assertEquals(InputProblem.CORRUPT_BAG, e.problem());
        assertTrue(e.getMessage().contains("CRC"), e.getMessage());
    }

    @Test
    void chunkThatLiesAboutItsSizeIsRefused() throws IOException {
        byte[] b = BagWriters.mcap(List.of(poseTopic()), "lz4", 100, true);
        int chunk = indexOfChunk(b);
        // chunk record: opcode, length u64, start u64, end u64, uncompressed size u64 at +25
        b[chunk + 25] += 3;
        InputException e = refused(b, "size.mcap", "/pose");
        assertEquals(InputProblem.CORRUPT_BAG, e.problem());
    }

    @Test
    void chunkLengthPastTheEndOfTheFileIsRefused() throws IOException {
        byte[] b = BagWriters.mcap(List.of(poseTopic()), "", 100, false);
        int chunk = indexOfChunk(b);
        b[chunk + 8] = 0x40; // record length's high byte: 2^62 bytes claimed
        InputException e = refused(b, "long.mcap", "/pose");
        assertEquals(InputProblem.CORRUPT_BAG, e.problem());
        assertTrue(e.getMessage().contains("remain"), e.getMessage());
    }

    @Test
    void unknownCompressionIsRefusedNamingIt() throws IOException {
        InputException e = refused(BagWriters.mcap(List.of(poseTopic()), "brotli", 100, true), "brotli.mcap", "/pose");
        assertEquals(InputProblem.UNSUPPORTED_BAG_FEATURE, e.problem());
        assertTrue(e.getMessage().contains("'brotli'"), e.getMessage());
    }

    @Test
    void definitionThatDoesNotParseIsRefusedNamingTheLine() throws IOException {
        BagWriters.Topic t = new BagWriters.Topic("/pose", "geometry_msgs/msg/PoseStamped",
                "std_msgs/Header header\nPose[abc pose\n");
        t.add(1, BagWriters.cdrPoseStamped(POSES.get(0)));
        InputException e = refused(BagWriters.mcap(List.of(t), "", 10, true), "schema.mcap", "/pose");
        assertEquals(InputProblem.CORRUPT_BAG, e.problem());
        assertTrue(e.getMessage().contains("does not parse") && e.getMessage().contains("line 2"), e.getMessage());
    }

    @Test
    void typeWithoutAPoseIsRefusedPointingToPoseField() throws IOException {
        BagWriters.Topic t = new BagWriters.Topic("/chatter", "std_msgs/msg/String", "string data\n");
        t.add(1, new byte[] {0, 1, 0, 0, 3, 0, 0, 0, 'h', 'i', 0});
        InputException e = refused(BagWriters.mcap(List.of(t), "", 10, true), "string.mcap", "/chatter");
        assertEquals(InputProblem.UNKNOWN_TOPIC, e.problem());
        assertTrue(e.getMessage().contains("--pose-field"), e.getMessage());
    }

    @Test
    void messageShorterThanItsTypeIsRefusedNamingTheMessage() throws IOException {
        BagWriters.Topic t = new BagWriters.Topic("/pose", "geometry_msgs/msg/PoseStamped", BagWriters.POSE_STAMPED_ROS2);
        t.add(1, BagWriters.cdrPoseStamped(POSES.get(0)));
        t.add(2, Arrays.copyOf(BagWriters.cdrPoseStamped(POSES.get(1)), 30));
        InputException e = refused(BagWriters.mcap(List.of(t), "", 10, true), "short.mcap", "/pose");
        assertEquals(InputProblem.CORRUPT_BAG, e.problem());
        assertTrue(e.getMessage().contains("message 2 of topic /pose"), e.getMessage());
    }

    @Test
    void unknownTypeIsReadThroughPoseField() throws IOException {
        String def = "std_msgs/Header header\nstring note\ngeometry_msgs/Pose estimate\n"
                + BagWriters.POSE_STAMPED_ROS2.substring(BagWriters.POSE_STAMPED_ROS2.indexOf("=====") - 1);
        BagWriters.Topic t = new BagWriters.Topic("/state", "my_msgs/msg/State", def);
        for (BagWriters.Pose p : POSES) {
            byte[] ps = BagWriters.cdrPoseStamped(p);
            // insert "note" (an empty string: u32 1 + NUL, then padding) between header and pose
            int headerEnd = 4 + 8 + 4 + p.frame().length() + 1;
            BagWriters.Out o = new BagWriters.Out();
            o.bytes(Arrays.copyOf(ps, headerEnd));
            o.origin = 4;
            o.align(4).u32(1).u8(0).align(8);
            o.bytes(Arrays.copyOfRange(ps, ps.length - 56, ps.length));
            t.add(p.stampNs(), o.toArray());
        }
        Path p = dir.resolve("state.mcap");
        Files.write(p, BagWriters.mcap(List.of(t), "", 10, true));
        InputException e = assertThrows(InputException.class,
                () -> BagTrajectoryReader.read(p, BagReadOptions.of("/state"), ReadOptions.defaults()));
        assertTrue(e.getMessage().contains("my_msgs/State") && e.getMessage().contains("--pose-field"), e.getMessage());
        LoadedTrajectory r = BagTrajectoryReader.read(p, new BagReadOptions("/state", StampSource.HEADER, "estimate",
                BagLimits.DEFAULT), ReadOptions.defaults());
        GeneratedBagsTest.assertPoses(POSES, r);
    }

    @Test
    void refusalWordingForAMissingTopic() throws IOException {
        Path p = dir.resolve("w.mcap");
        Files.write(p, BagWriters.mcap(List.of(poseTopic()), "", 100, true));
        InputException e = assertThrows(InputException.class,
                () -> BagTrajectoryReader.read(p, BagReadOptions.of("/odom"), ReadOptions.defaults()));
        assertEquals(p + ": the bag has no topic /odom; its topics are: /pose (geometry_msgs/msg/PoseStamped), found "
                + "\"/odom\"", e.getMessage());
    }

    private static int indexOfChunk(byte[] b) {
        // first record with opcode 0x06 after the magic, header, schema and channel records
        int at = McapReader.MAGIC.length;
        while (b[at] != 0x06) {
            at += 9 + (int) ByteCursor.le64(b, at + 1);
        }
        return at;
    }

    private static int lastIndexOf(byte[] hay, byte[] needle) {
        outer:
        for (int i = hay.length - needle.length; i >= 0; i--) {
            for (int k = 0; k < needle.length; k++) {
                if (hay[i + k] != needle[k]) {
                    continue outer;
                }
            }
            return i;
        }
        throw new AssertionError("not found");
    }
}
