package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;

class SortingTest {
    private static final ReadOptions SORT = ReadOptions.defaults().withOrder(TimestampOrder.SORT);

    @Test
    void permutedCsvRowsWithSortReadAsTheSortedFile(@TempDir Path dir) throws IOException {
        Random rnd = new Random(11);
        List<String> rows = new ArrayList<>();
        for (int i = 0; i < 3000; i++) {
            rows.add((i * 0.01 + rnd.nextDouble() * 0.001) + "," + rnd.nextGaussian() + "," + rnd.nextGaussian() + ","
                    + rnd.nextGaussian());
        }
        Path sorted = write(dir.resolve("sorted.csv"), "t,x,y,yaw", rows);
        List<String> shuffled = new ArrayList<>(rows);
        Collections.shuffle(shuffled, rnd);
        Path permuted = write(dir.resolve("permuted.csv"), "t,x,y,yaw", shuffled);

        PlanarTrajectory expected = (PlanarTrajectory) TrajectoryReader.read(sorted, ReadOptions.defaults()).trajectory();
        PlanarTrajectory actual = (PlanarTrajectory) TrajectoryReader.read(permuted, SORT).trajectory();

        assertArrayEquals(expected.timestamps(), actual.timestamps());
        assertArrayEquals(expected.xs(), actual.xs());
        assertArrayEquals(expected.ys(), actual.ys());
        assertArrayEquals(expected.yaws(), actual.yaws());
        assertEquals(InputProblem.DECREASING_TIMESTAMP, assertThrows(InputException.class,
                () -> TrajectoryReader.read(permuted, ReadOptions.defaults())).problem());
    }

    @Test
    void permutedTumRowsWithSortReadAsTheSortedFile(@TempDir Path dir) throws IOException {
        List<String> rows = new ArrayList<>();
        for (int i = 0; i < 500; i++) {
            double a = 0.01 * i;
            rows.add((1.3e9 + 0.1 * i) + " " + i + " " + (2 * i) + " " + (3 * i) + " 0 0 " + Math.sin(a) + " "
                    + Math.cos(a));
        }
        Path sorted = write(dir.resolve("sorted.txt"), "# t tx ty tz qx qy qz qw", rows);
        List<String> reversed = new ArrayList<>(rows);
        Collections.reverse(reversed);
        Path permuted = write(dir.resolve("reversed.txt"), "# reversed", reversed);

        SpatialTrajectory expected = (SpatialTrajectory) TrajectoryReader.read(sorted, ReadOptions.defaults()).trajectory();
        SpatialTrajectory actual = (SpatialTrajectory) TrajectoryReader.read(permuted, SORT).trajectory();
        assertEquals(expected.size(), actual.size());
        for (int i = 0; i < expected.size(); i++) {
            assertEquals(expected.t(i), actual.t(i), 0.0);
            assertEquals(expected.x(i), actual.x(i), 0.0);
            assertEquals(expected.qw(i), actual.qw(i), 0.0);
            assertEquals(expected.qz(i), actual.qz(i), 0.0);
        }
    }

    @Test
    void stableOrderKeepsEqualKeysInFileOrder() {
        double[] key = {3, 1, 2, 1, 0, 2};
        assertArrayEquals(new int[] {4, 1, 3, 2, 5, 0}, PoseBuffer.stableOrder(key, key.length));
    }

    @Test
    void sortRefusesARepeatedTimestampNamingBothLines(@TempDir Path dir) throws IOException {
        // lines 2..6: 0.5, 0.2, 0.9, 0.2, 0.1 -> lines 3 and 5 share 0.2 s
        Path file = write(dir.resolve("dup.csv"), "t,x,y,yaw", List.of("0.5,0,0,0", "0.2,0,0,0", "0.9,0,0,0",
                "0.2,1,1,1", "0.1,0,0,0"));
        InputException e = assertThrows(InputException.class, () -> TrajectoryReader.read(file, SORT));
        assertEquals(InputProblem.DUPLICATE_TIMESTAMP, e.problem());
        assertEquals(5, e.line());
        assertEquals(file + ":5: column 't' repeats the timestamp of line 3 (0.2 s): timestamps must be unique"
                + " (--sort does not remove duplicates; --duplicates keep keeps both poses, as evo does), found \"0.2\"",
                e.getMessage());
    }

    @Test
    void keptDuplicatesStayInFileOrderWhenSorted(@TempDir Path dir) throws IOException {
        // lines 2..5: t = 0.5, 0.2, 0.9, 0.2 with x = 1, 2, 3, 4 -> sorted x = 2, 4, 1, 3
        Path file = write(dir.resolve("dup.csv"), "t,x,y,yaw", List.of("0.5,1,0,0", "0.2,2,0,0", "0.9,3,0,0",
                "0.2,4,0,0"));
        PlanarTrajectory t = (PlanarTrajectory) TrajectoryReader.read(file,
                SORT.withDuplicates(DuplicateTimestamps.KEEP)).trajectory();
        assertArrayEquals(new double[] {0.2, 0.2, 0.5, 0.9}, t.timestamps());
        assertArrayEquals(new double[] {2, 4, 1, 3}, t.xs());
    }

    private static Path write(Path p, String header, List<String> rows) throws IOException {
        List<String> all = new ArrayList<>();
        all.add(header);
        all.addAll(rows);
        return Files.write(p, all);
    }
}
