package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Readers hand their columns over as filled, without a copy trimmed to the pose count (KITTI, the
 * Euler-angle formats): the trajectories still hold exactly that many poses with the values read,
 * and a KITTI times file sorted with --sort carries every pose's position and rotation along with
 * its time.
 */
class HandedOverColumnsTest {
    @TempDir
    Path dir;

    @Test
    void sortedTimesCarryTheirPosesAlong() throws IOException {
        // pose i: rotation of i * 10 deg about z (rounded to 6 digits as written), position (i, 10 i, 100 i);
        // times 2, 1, 3 s: sorted, the poses come in the order 1, 0, 2 (by hand)
        Path poses = write("sort.txt", pose(0) + pose(1) + pose(2));
        Path times = write("sort_times.txt", "2.0\n1.0\n3.0\n");
        SpatialTrajectory t = (SpatialTrajectory) TrajectoryReader.read(poses, ReadOptions.defaults()
                .withFormat(TrajectoryFormat.KITTI).withKittiTimes(times).withOrder(TimestampOrder.SORT)).trajectory();
        assertEquals(3, t.size());
        int[] order = {1, 0, 2};
        double[] r = new double[9];
        for (int k = 0; k < 3; k++) {
            int i = order[k];
            assertEquals(k == 0 ? 1.0 : k == 1 ? 2.0 : 3.0, t.t(k), 0.0);
            assertEquals(i, t.x(k), 0.0);
            assertEquals(10.0 * i, t.y(k), 0.0);
            assertEquals(100.0 * i, t.z(k), 0.0);
            t.rotation(k, r, 0);
            assertArrayEquals(rotation(i), r, 0.0);
        }
    }

    @Test
    void manyPosesGiveExactlyThatManyWithAndWithoutTimes() throws IOException {
        // 30 000 poses, enough for the buffer to size itself from the file (its columns may be longer)
        int n = 30_000;
        StringBuilder p = new StringBuilder();
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < n; i++) {
            p.append(pose(i % 36));
            s.append(0.5 * i).append('\n');
        }
        Path poses = write("many.txt", p.toString());
        Path times = write("many_times.txt", s.toString());
        int last = n - 1; // 29 999 = 833 * 36 + 11: pose(11)
        for (ReadOptions o : new ReadOptions[] {ReadOptions.defaults().withFormat(TrajectoryFormat.KITTI),
            ReadOptions.defaults().withFormat(TrajectoryFormat.KITTI).withKittiTimes(times)}) {
            SpatialTrajectory t = (SpatialTrajectory) TrajectoryReader.read(poses, o).trajectory();
            assertEquals(n, t.size());
            assertEquals(n, t.poses().size());
            assertEquals(o.kittiTimes() == null ? last : 0.5 * last, t.t(last), 0.0);
            assertEquals(110.0, t.y(last), 0.0);
            assertEquals(1100.0, t.z(last), 0.0);
            double[] r = new double[9];
            t.rotation(last, r, 0);
            assertArrayEquals(rotation(11), r, 0.0);
        }
    }

    @Test
    void manyNcltPosesGiveExactlyThatMany() throws IOException {
        // 30 000 NCLT rows (utime us, x, y, z, roll, pitch, yaw): enough for the buffer to size itself
        // from the file; pose i at utime 1e15 + 1e4 i, x = i, z = 0.25 (by hand: t = utime / 1e6)
        int n = 30_000;
        StringBuilder p = new StringBuilder();
        for (int i = 0; i < n; i++) {
            p.append(1_000_000_000_000_000L + 10_000L * i).append(',').append(i).append(",2,0.25,0,0,0.5\n");
        }
        Path file = write("groundtruth.csv", p.toString());
        SpatialTrajectory t = (SpatialTrajectory) TrajectoryReader.read(file,
                ReadOptions.defaults().withFormat(TrajectoryFormat.NCLT)).trajectory();
        assertEquals(n, t.size());
        assertEquals(n, t.poses().size());
        assertEquals((1_000_000_000_000_000L + 10_000L * (n - 1)) / 1e6, t.t(n - 1), 0.0);
        assertEquals(n - 1, t.x(n - 1), 0.0);
        assertEquals(0.25, t.z(n - 1), 0.0);
        assertEquals(Math.cos(0.25), t.qw(n - 1), 1e-15); // yaw 0.5 alone: (cos 0.25, 0, 0, sin 0.25)
    }

    private Path write(String name, String text) throws IOException {
        Path file = dir.resolve(name);
        Files.writeString(file, text, StandardCharsets.US_ASCII);
        return file;
    }

    /** One KITTI line: rotation of i * 10 deg about z (6 digits), position (i, 10 i, 100 i). */
    private static String pose(int i) {
        double[] r = rotation(i);
        return String.format(java.util.Locale.ROOT, "%s %s %s %d %s %s %s %d %s %s %s %d%n", r[0], r[1], r[2], i, r[3],
                r[4], r[5], 10 * i, r[6], r[7], r[8], 100 * i);
    }

    private static double[] rotation(int i) {
        double c = Math.rint(Math.cos(Math.toRadians(10.0 * i)) * 1e6) / 1e6;
        double s = Math.rint(Math.sin(Math.toRadians(10.0 * i)) * 1e6) / 1e6;
        return new double[] {c, -s, 0, s, c, 0, 0, 0, 1};
    }
}
