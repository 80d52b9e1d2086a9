package org.trajeval.core.assoc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.RefData;
import org.trajeval.core.eval.AlignmentWarningsTest;
import org.trajeval.core.report.EvaluationReport;

/** --t-offset auto recovers known clock offsets, on seeded planar data and on real TUM data. */
class ClockOffsetTest {
    /** "to within a few ms" (issue 10). */
    private static final double OFFSET_TOL_S = 0.003;

    @TempDir
    Path dir;

    /** A seeded planar run at 50 Hz for 40 s with an irregular yaw rate; the estimate is noisy. */
    private void writePlanarPair(Path gt, Path est, double estClockAheadS, long seed) throws IOException {
        Random rnd = new Random(seed);
        StringBuilder g = new StringBuilder("t,x,y,yaw\n");
        StringBuilder e = new StringBuilder("t,x,y,yaw\n");
        double x = 0;
        double y = 0;
        double yaw = 0;
        double rate = 0;
        for (int i = 0; i < 2000; i++) {
            double t = 100.0 + i * 0.02;
            rate = 0.95 * rate + 0.3 * rnd.nextGaussian();
            yaw += rate * 0.02;
            x += 0.02 * Math.cos(yaw);
            y += 0.02 * Math.sin(yaw);
            g.append(String.format(Locale.ROOT, "%.4f,%.6f,%.6f,%.6f%n", t, x, y, yaw));
            if (i % 2 == 0) {
                e.append(String.format(Locale.ROOT, "%.4f,%.6f,%.6f,%.6f%n", t + estClockAheadS,
                        x + 0.01 * rnd.nextGaussian(), y + 0.01 * rnd.nextGaussian(), yaw + 0.005 * rnd.nextGaussian()));
            }
        }
        Files.write(gt, g.toString().getBytes(StandardCharsets.UTF_8));
        Files.write(est, e.toString().getBytes(StandardCharsets.UTF_8));
    }

    @Test
    void autoOffsetRecoversAKnownOffsetOnSeededPlanarData() throws IOException {
        for (double ahead : new double[] {0.3, -0.25, 0.12}) {
            Path gt = dir.resolve("gt" + ahead + ".csv");
            Path est = dir.resolve("est" + ahead + ".csv");
            writePlanarPair(gt, est, ahead, 11);
            EvaluationReport r = AlignmentWarningsTest.evaluate(gt, est, "t_offset_s", "auto");
            // the estimate's clock runs `ahead` s ahead: the offset to add is -ahead (by construction)
            assertEquals(-ahead, r.association().tOffsetS(), OFFSET_TOL_S, "ahead " + ahead);
            assertNotNull(r.association().tOffsetAuto());
            assertTrue(r.association().tOffsetAuto().uncertaintyS() < 0.05, r.association().tOffsetAuto().toString());
        }
    }

    @Test
    void autoOffsetRecoversAnOffsetAddedToFreiburg1Xyz() throws IOException {
        Path d = RefData.dir();
        Path gt = d.resolve("freiburg1_xyz-groundtruth.txt");
        Path est = d.resolve("freiburg1_xyz-rgbdslam.txt");
        double base = AlignmentWarningsTest.evaluate(gt, est, "t_offset_s", "auto").association().tOffsetS();
        List<String> shifted = new ArrayList<>();
        for (String line : Files.readAllLines(est)) {
            if (line.startsWith("#") || line.isBlank()) {
                shifted.add(line);
                continue;
            }
            String[] f = line.trim().split("\\s+");
            f[0] = String.format(Locale.ROOT, "%.4f", Double.parseDouble(f[0]) + 0.25);
            shifted.add(String.join(" ", f));
        }
        Path moved = dir.resolve("rgbdslam_plus_250ms.txt");
        Files.write(moved, shifted);
        EvaluationReport r = AlignmentWarningsTest.evaluate(gt, moved, "t_offset_s", "auto");
        // stamps moved 0.25 s later: the recovered offset moves by -0.25 s from the one of the original pair
        assertEquals(base - 0.25, r.association().tOffsetS(), OFFSET_TOL_S, "base " + base);
        assertTrue(Math.abs(base) < 0.05, "the original pair is nearly synchronous: " + base);
    }
}
