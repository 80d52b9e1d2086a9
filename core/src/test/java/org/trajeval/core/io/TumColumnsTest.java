package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * A TUM line {@code t tx ty tz qx qy qz qw} is stored in the columns t, x, y, z, qw, qx, qy, qz
 * (the quaternion's w moved first): every stored value must carry the bits of
 * {@link Double#parseDouble} of the field it comes from.
 */
class TumColumnsTest {
    /** Field of a TUM line that each stored column comes from: t x y z, then qw (field 7), qx, qy, qz. */
    private static final int[] FIELD_OF_COLUMN = {0, 1, 2, 3, 7, 4, 5, 6};

    @Test
    void everyValueOfARealTumFileIsStoredWithTheBitsOfItsField() throws IOException {
        assertColumnsCarryTheFields(RefdataReadingTest.refdata("freiburg1_xyz-groundtruth.txt"));
    }

    @Test
    void seededLinesAcrossBatchesAndGrowthAreStoredWithTheBitsOfTheirFields(@TempDir Path dir) throws IOException {
        // 10 000 lines (batches of 4096 poses, columns grown from 1024); random digits and signs, unit quaternions
        // written to 9 decimals (norm within 1e-8 of 1, far inside the default tolerance)
        SplittableRandom rnd = new SplittableRandom(15);
        StringBuilder sb = new StringBuilder("# t tx ty tz qx qy qz qw\n");
        for (int i = 0; i < 10_000; i++) {
            double[] q = {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
            double norm = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
            String tx = String.format(Locale.ROOT, "%." + rnd.nextInt(9) + "f", (rnd.nextDouble() - 0.5) * 2000);
            sb.append(String.format(Locale.ROOT, "%.6f %s %.4f %.9f %.9f %.9f %.9f %.9f%n", 1.0e6 + i * 0.01,
                    tx, (rnd.nextDouble() - 0.5) * 50,
                    rnd.nextDouble() - 0.5, q[0] / norm, q[1] / norm, q[2] / norm, q[3] / norm));
        }
        Path file = Files.writeString(dir.resolve("seeded.tum"), sb);
        assertColumnsCarryTheFields(file);
    }

    private static void assertColumnsCarryTheFields(Path file) throws IOException {
        List<String[]> lines = new ArrayList<>();
        for (String line : Files.readAllLines(file)) {
            if (!line.isBlank() && !line.strip().startsWith("#")) {
                lines.add(line.strip().split("[ \t]+"));
            }
        }
        SpatialTrajectory t = (SpatialTrajectory) TrajectoryReader.read(file, ReadOptions.defaults()).trajectory();
        assertEquals(lines.size(), t.size());
        for (int i = 0; i < lines.size(); i++) {
            double[] stored = {t.t(i), t.x(i), t.y(i), t.z(i), t.qw(i), t.qx(i), t.qy(i), t.qz(i)};
            for (int c = 0; c < 8; c++) {
                String field = lines.get(i)[FIELD_OF_COLUMN[c]];
                assertEquals(Double.doubleToRawLongBits(Double.parseDouble(field)),
                        Double.doubleToRawLongBits(stored[c]), "pose " + i + " column " + c + ": " + field);
            }
        }
    }
}
