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

    private static final byte[] IMAGE = new byte[64];

    static {
        for (int i = 0; i < IMAGE.length; i++) {
            IMAGE[i] = (byte) (37 * i + 11);
        }
    }

    private static BagWriters.Topic imageTopic() {
        BagWriters.Topic t = new BagWriters.Topic("/image", "sensor_msgs/msg/Image", "uint8[] data\n");
        for (BagWriters.Pose p : POSES) {
            t.add(p.stampNs() + 1, IMAGE);
        }
        return t;
    }

    /** Reads with every checksum (bag_crc: all), the strictest reading, and expects a refusal. */
    private InputException refused(byte[] bytes, String name, String topic) throws IOException {
        Path p = dir.resolve(name);
        Files.write(p, bytes);
        InputException e = assertThrows(InputException.class,
                () -> BagTrajectoryReader.read(p, new BagReadOptions(topic, StampSource.HEADER, null,
                        BagLimits.DEFAULT, BagIntegrity.ALL), ReadOptions.defaults()));
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
        BagWriters.resealDataCrc(b); // so the chunk's own CRC is what finds it
        InputException e = refused(b, "crc.mcap", "/pose");
        assertEquals(InputProblem.CORRUPT_BAG, e.problem());
        assertTrue(e.getMessage().contains("CRC of the uncompressed records mismatch"), e.getMessage());
    }

    @Test
    void byteFlippedInAChunkNoWantedTopicUsesIsRefusedByTheDataSectionCrcNamingItsOffset() throws IOException {
        for (boolean summary : new boolean[] {true, false}) {
            byte[] b = BagWriters.mcap(List.of(poseTopic(), imageTopic()), "", 5, summary);
            int dataEnd = lastIndexOf(b, new byte[] {0x0F, 4, 0, 0, 0, 0, 0, 0, 0});
            b[lastIndexOf(b, IMAGE) + 17] ^= 0x01; // inside an image message: the /pose chunks stay intact
            InputException e = refused(b, "flipped.mcap", "/pose");
            assertEquals(InputProblem.CORRUPT_BAG, e.problem());
            assertEquals("byte " + dataEnd, e.column(), e.getMessage());
            assertTrue(e.getMessage().contains("at byte " + dataEnd + ": data section CRC mismatch"), e.getMessage());
        }
    }

    @Test
    void integrityChunksByDefaultSkipsTheDataSectionPassButStillChecksTheChunksRead() throws IOException {
        // the 40 images logged after the 40 poses: chunks of 5 are pose-only, then image-only
        BagWriters.Topic late = new BagWriters.Topic("/image", "sensor_msgs/msg/Image", "uint8[] data\n");
        for (BagWriters.Pose q : POSES) {
            late.add(q.stampNs() + 1_000_000_000_000L, IMAGE);
        }
        byte[] b = BagWriters.mcap(List.of(poseTopic(), late), "", 5, true);
        b[lastIndexOf(b, IMAGE) + 17] ^= 0x01; // in an image chunk: only the data section CRC can see it
        Path p = dir.resolve("chunks.mcap");
        Files.write(p, b);
        BagReadOptions chunks = BagReadOptions.of("/pose"); // the default is chunks
        assertEquals(POSES.size(), BagTrajectoryReader.read(p, chunks, ReadOptions.defaults()).trajectory().size());
        assertTrue(refused(b, "chunks-all.mcap", "/pose").getMessage().contains("data section CRC mismatch"));

        byte[] c = BagWriters.mcap(List.of(poseTopic(), imageTopic()), "", 5, true);
        int at = lastIndexOf(c, BagWriters.cdrPoseStamped(POSES.get(POSES.size() - 1))) + 60;
        c[at] ^= 0x10; // in a pose chunk: its own CRC refuses it under either choice
        Files.write(p, c);
        InputException e = assertThrows(InputException.class,
                () -> BagTrajectoryReader.read(p, chunks, ReadOptions.defaults()));
        assertTrue(e.getMessage().contains("CRC of the uncompressed records mismatch"), e.getMessage());
    }

    @Test
    void dataSectionCrcZeroMeansNotComputedAndTheWantedChunksStillRead() throws IOException {
        byte[] b = BagWriters.mcap(List.of(poseTopic(), imageTopic()), "lz4", 5, true);
        int dataEnd = lastIndexOf(b, new byte[] {0x0F, 4, 0, 0, 0, 0, 0, 0, 0});
        Arrays.fill(b, dataEnd + 9, dataEnd + 13, (byte) 0); // CRC 0: "not available" (mcap.dev/spec, Data End)
        Path p = dir.resolve("nocrc.mcap");
        Files.write(p, b);
        assertEquals(POSES.size(), BagTrajectoryReader.read(p, BagReadOptions.of("/pose"), ReadOptions.defaults())
                .trajectory().size());
    }

    @Test
    void everyFlippedByteOfTheRealMcapIsRefusedOrChangesNothing() throws IOException {
        // nav2_turtlebot.mcap (rosbag2's writer) has chunk CRCs and no data section CRC (0): a byte
        // flipped in a chunk of /odom is found by that chunk's CRC (or its zstd frame); one elsewhere
        // may go unseen, but then the trajectory must be the intact one
        Path real = BagEvoParityTest.rosData().resolve("nav2_turtlebot.mcap");
        ReadOptions keep = ReadOptions.defaults().withDuplicates(org.trajeval.core.io.DuplicateTimestamps.KEEP);
        byte[] whole = Files.readAllBytes(real);
        double[] intact = flat(BagTrajectoryReader.read(real, BagReadOptions.of("/odom"), keep));
        java.util.Random r = new java.util.Random(13);
        Path p = dir.resolve("flipped-real.mcap");
        int refusals = 0;
        for (int i = 0; i < 40; i++) {
            byte[] b = whole.clone();
            b[8 + r.nextInt(whole.length - 16)] ^= (byte) (1 << r.nextInt(8));
            Files.write(p, b);
            try {
                double[] x = flat(BagTrajectoryReader.read(p, BagReadOptions.of("/odom"), keep));
                assertTrue(Arrays.equals(intact, x), "flip " + i + " changed the poses without a refusal");
            } catch (InputException e) {
                assertFalse(e.getMessage().contains("\n"), e.getMessage());
                refusals++;
            }
        }
        assertTrue(refusals > 0, "some flips land in /odom's chunks and must be refused");
    }

    @Test
    void chunkThatLiesAboutItsSizeIsRefused() throws IOException {
        byte[] b = BagWriters.mcap(List.of(poseTopic()), "lz4", 100, true);
        int chunk = indexOfChunk(b);
        // chunk record: opcode, length u64, start u64, end u64, uncompressed size u64 at +25
        b[chunk + 25] += 3;
        BagWriters.resealDataCrc(b);
        InputException e = refused(b, "size.mcap", "/pose");
        assertEquals(InputProblem.CORRUPT_BAG, e.problem());
    }

    @Test
    void chunkLengthPastTheEndOfTheFileIsRefused() throws IOException {
        byte[] b = BagWriters.mcap(List.of(poseTopic()), "", 100, false);
        int chunk = indexOfChunk(b);
        b[chunk + 8] = 0x40; // record length's high byte: 2^62 bytes claimed
        int dataEnd = lastIndexOf(b, new byte[] {0x0F, 4, 0, 0, 0, 0, 0, 0, 0});
        Arrays.fill(b, dataEnd + 9, dataEnd + 13, (byte) 0); // no data section CRC: the scan meets the length
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

    /** @return t, x, y, z, qw, qx, qy, qz of every pose, one after the other */
    private static double[] flat(LoadedTrajectory t) {
        org.trajeval.core.traj.SpatialTrajectory s = t.trajectory().toSpatial();
        double[] out = new double[8 * s.size()];
        for (int i = 0; i < s.size(); i++) {
            double[] v = {s.t(i), s.x(i), s.y(i), s.z(i), s.qw(i), s.qx(i), s.qy(i), s.qz(i)};
            System.arraycopy(v, 0, out, 8 * i, 8);
        }
        return out;
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
