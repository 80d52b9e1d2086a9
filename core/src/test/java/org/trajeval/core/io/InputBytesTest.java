package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.FileNotFoundException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.RefData;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * A file read from a stream into memory ({@link InputBytes}, how trajeval-spark reads hdfs: and s3a:
 * files) gives what the same file gives from a local disk: format, format reason, every number bit
 * for bit and the SHA-256; only the source differs (the name as given). Chunks far smaller than the
 * files make every line cross chunk boundaries somewhere.
 */
class InputBytesTest {
    /** Small chunks: the refdata files span 4 to 700 of them. */
    private static final int SMALL_CHUNK_BYTES = 4093;

    @TempDir
    Path tmp;

    private static final String URI = "hdfs://127.0.0.1:9000/fleet/";

    @Test
    void everyReferenceFileReadFromBytesEqualsTheLocalRead() throws Exception {
        String[] files = {"freiburg1_xyz-groundtruth.txt", "freiburg1_xyz-ORB_kf_mono.txt", "V102_groundtruth.csv",
            "fr2_desk_ORB.txt", "KITTI_00_gt.txt", "georeferenced.tum"};
        for (String f : files) {
            Path local = RefData.dir().resolve(f);
            sameAsLocal(local, ReadOptions.defaults());
        }
    }

    @Test
    void aPlanarCsvWithQuotedFieldsReadFromBytesEqualsTheLocalRead() throws Exception {
        Path csv = tmp.resolve("run.csv");
        StringBuilder text = new StringBuilder("t,x,y,yaw,\"note\"\n");
        for (int i = 0; i < 3000; i++) {
            text.append(i * 0.1).append(',').append(Math.cos(i * 0.01)).append(',').append(Math.sin(i * 0.01))
                    .append(',').append(i * 0.001).append(",\"a, b\"\n");
        }
        Files.writeString(csv, text);
        sameAsLocal(csv, ReadOptions.defaults());
    }

    private void sameAsLocal(Path local, ReadOptions options) throws Exception {
        String name = URI + local.getFileName();
        LoadedTrajectory expected = TrajectoryReader.read(local, options);
        InputBytes bytes = InputBytes.read(name, () -> Files.newInputStream(local), options.maxBytes(),
                SMALL_CHUNK_BYTES);
        assertEquals(Files.size(local), bytes.size(), local + ": every byte held");
        LoadedTrajectory got = TrajectoryReader.read(bytes, options);
        assertEquals(name, got.source(), "the source is the name as given");
        assertEquals(expected.format(), got.format(), local.toString());
        assertEquals(expected.formatReason(), got.formatReason(), local.toString());
        assertEquals(expected.sha256(), got.sha256(), local + ": SHA-256 of the same bytes");
        assertEquals(expected.indexTimestamps(), got.indexTimestamps());
        SpatialTrajectory a = expected.trajectory().toSpatial();
        SpatialTrajectory b = got.trajectory().toSpatial();
        assertEquals(a.size(), b.size(), local.toString());
        double[] qa = new double[4];
        double[] qb = new double[4];
        for (int i = 0; i < a.size(); i++) {
            assertEquals(Double.doubleToLongBits(a.t(i)), Double.doubleToLongBits(b.t(i)), local + " t " + i);
            assertEquals(Double.doubleToLongBits(a.x(i)), Double.doubleToLongBits(b.x(i)), local + " x " + i);
            assertEquals(Double.doubleToLongBits(a.y(i)), Double.doubleToLongBits(b.y(i)), local + " y " + i);
            assertEquals(Double.doubleToLongBits(a.z(i)), Double.doubleToLongBits(b.z(i)), local + " z " + i);
            a.quaternion(i, qa);
            b.quaternion(i, qb);
            assertArrayEquals(qa, qb, 0.0, local + " q " + i);
        }
    }

    @Test
    void badBytesAreRefusedNamingTheUri() {
        ReadOptions o = ReadOptions.defaults();
        InputException empty = assertThrows(InputException.class,
                () -> TrajectoryReader.read(bytes("empty.txt", new byte[0]), o));
        assertEquals(InputProblem.EMPTY, empty.problem());
        assertEquals(URI + "empty.txt", empty.source());

        byte[] utf16 = "\uFEFF1 2 3 4 5 6 7 8\n".getBytes(StandardCharsets.UTF_16LE);
        InputException wide = assertThrows(InputException.class, () -> TrajectoryReader.read(bytes("w.txt", utf16), o));
        assertEquals(InputProblem.NOT_UTF8, wide.problem());

        byte[] ten = "0 1 2 3 0 0 0 1\n".repeat(10).getBytes(StandardCharsets.US_ASCII);
        InputException big = assertThrows(InputException.class,
                () -> InputBytes.read(URI + "big.txt", () -> new ByteArrayInputStream(ten), 100));
        assertEquals(InputProblem.TOO_LARGE, big.problem());
        assertEquals(URI + "big.txt", big.source());

        InputException missing = assertThrows(InputException.class, () -> InputBytes.read(URI + "gone.txt", () -> {
            throw new FileNotFoundException("File does not exist: /fleet/gone.txt");
        }, o.maxBytes()));
        assertEquals(InputProblem.UNREADABLE, missing.problem());
        assertEquals("the file does not exist", missing.detail());
    }

    @Test
    void aRosBagFromAStreamIsRefusedWithTheReason() throws Exception {
        Path bag = RefData.dir().resolve("ros/ROS_example.bag");
        InputBytes b = InputBytes.read(URI + "ROS_example.bag", () -> Files.newInputStream(bag), Long.MAX_VALUE);
        InputException e = assertThrows(InputException.class, () -> TrajectoryReader.read(b, ReadOptions.defaults()));
        assertEquals(InputProblem.UNREADABLE, e.problem());
        assertTrue(e.getMessage().contains("read from a local file only"), e.getMessage());
    }

    @Test
    void theExtensionOfTheUriStillChoosesTheFormat() {
        byte[] tum = "1.0 0 0 0 0 0 0 1\n2.0 1 0 0 0 0 0 1\n".getBytes(StandardCharsets.US_ASCII);
        LoadedTrajectory t = TrajectoryReader.read(bytes("run.tum", tum), ReadOptions.defaults());
        assertEquals(TrajectoryFormat.TUM, t.format());
        assertEquals("auto: extension .tum (TUM)", t.formatReason());
    }

    private static InputBytes bytes(String file, byte[] content) {
        return InputBytes.read(URI + file, () -> new ByteArrayInputStream(content), Long.MAX_VALUE);
    }
}
