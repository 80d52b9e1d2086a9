package org.trajeval.core.property;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TimestampOrder;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Reading a file whose rows are permuted with {@link TimestampOrder#SORT} ({@code --sort})
 * gives the same trajectory, bit for bit, as reading the sorted file, and so the same
 * evaluation. Rows are written with {@link Double#toString}, which round-trips exactly.
 */
class SortPropertyTest {
    @TempDir
    Path dir;

    static long[] seeds() {
        return java.util.stream.LongStream.range(1, 21).toArray();
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void permutedCsvRowsReadWithSortGiveTheSameTrajectoryAndResult(long seed) throws IOException {
        Random rnd = new Random(seed);
        PlanarTrajectory truth = RandomTrajectories.planarPath(rnd, 300, 0.1);
        PlanarTrajectory est = RandomTrajectories.noisy(rnd, truth, 0.05);
        List<String> rows = new ArrayList<>();
        for (int i = 0; i < est.size(); i++) {
            rows.add(est.t(i) + "," + est.x(i) + "," + est.y(i) + "," + est.yaw(i));
        }
        Path sorted = write("sorted.csv", "t,x,y,yaw", rows);
        Collections.shuffle(rows, rnd);
        Path permuted = write("permuted.csv", "t,x,y,yaw", rows);
        LoadedTrajectory a = TrajectoryReader.read(sorted, ReadOptions.defaults());
        LoadedTrajectory b = TrajectoryReader.read(permuted, ReadOptions.defaults().withOrder(TimestampOrder.SORT));
        PlanarTrajectory pa = (PlanarTrajectory) a.trajectory();
        PlanarTrajectory pb = (PlanarTrajectory) b.trajectory();
        assertArrayEquals(pa.timestamps(), pb.timestamps());
        assertArrayEquals(pa.xs(), pb.xs());
        assertArrayEquals(pa.ys(), pb.ys());
        for (int i = 0; i < pa.size(); i++) {
            assertEquals(pa.yaw(i), pb.yaw(i), 0.0);
        }
        LoadedTrajectory ref = RandomTrajectories.loaded("gt", truth);
        EvaluationReport ra = Evaluator.evaluate(ref, a, EvaluationOptions.preset(Convention.LESSON));
        EvaluationReport rb = Evaluator.evaluate(ref, b, EvaluationOptions.preset(Convention.LESSON));
        assertEquals(ra.ate(), rb.ate());
        assertEquals(ra.rpe(), rb.rpe());
    }

    @ParameterizedTest(name = "seed {0}")
    @MethodSource("seeds")
    void permutedTumRowsReadWithSortGiveTheSameTrajectory(long seed) throws IOException {
        Random rnd = new Random(seed);
        SpatialTrajectory est = RandomTrajectories.spatialPath(rnd, 300, 0.1, 0.02);
        List<String> rows = new ArrayList<>();
        for (int i = 0; i < est.size(); i++) {
            rows.add(est.t(i) + " " + est.x(i) + " " + est.y(i) + " " + est.z(i) + " " + est.qx(i) + " "
                    + est.qy(i) + " " + est.qz(i) + " " + est.qw(i));
        }
        Path sorted = write("sorted.txt", null, rows);
        Collections.shuffle(rows, rnd);
        Path permuted = write("permuted.txt", null, rows);
        SpatialTrajectory a = (SpatialTrajectory) TrajectoryReader.read(sorted, ReadOptions.defaults()).trajectory();
        SpatialTrajectory b = (SpatialTrajectory) TrajectoryReader.read(permuted,
                ReadOptions.defaults().withOrder(TimestampOrder.SORT)).trajectory();
        assertEquals(a.size(), b.size());
        for (int i = 0; i < a.size(); i++) {
            assertEquals(a.t(i), b.t(i), 0.0);
            assertEquals(a.x(i), b.x(i), 0.0);
            assertEquals(a.y(i), b.y(i), 0.0);
            assertEquals(a.z(i), b.z(i), 0.0);
            assertEquals(a.qw(i), b.qw(i), 0.0);
            assertEquals(a.qx(i), b.qx(i), 0.0);
            assertEquals(a.qy(i), b.qy(i), 0.0);
            assertEquals(a.qz(i), b.qz(i), 0.0);
        }
    }

    private Path write(String name, String header, List<String> rows) throws IOException {
        StringBuilder sb = new StringBuilder();
        if (header != null) {
            sb.append(header).append('\n');
        }
        for (String r : rows) {
            sb.append(r).append('\n');
        }
        Path p = dir.resolve(name);
        Files.write(p, sb.toString().getBytes(StandardCharsets.US_ASCII));
        return p;
    }
}
