package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;

class TrajectoryWriterTest {

    private static double anyFinite(SplittableRandom rnd) {
        switch (rnd.nextInt(4)) {
            case 0:
                double d;
                do {
                    d = Double.longBitsToDouble(rnd.nextLong());
                } while (!Double.isFinite(d));
                return d;
            case 1:
                return new double[] {-0.0, 0.0, Double.MIN_VALUE, -Double.MAX_VALUE, 1e-300, 123456789.123456789}[
                        rnd.nextInt(6)];
            default:
                return rnd.nextDouble(-1e4, 1e4);
        }
    }

    /** A finite position within the readers' bound of 1e9 m (OUT_OF_RANGE beyond): the fmod keeps varied bits. */
    private static double anyPosition(SplittableRandom rnd) {
        double d = anyFinite(rnd);
        return Math.abs(d) <= 1e9 ? d : Math.copySign(Math.abs(d) % 1e9, d);
    }

    @Test
    void planarCsvRoundTripIsBitExact(@TempDir Path dir) throws IOException {
        SplittableRandom rnd = new SplittableRandom(3);
        int n = 20_000;
        double[] t = new double[n];
        double[] x = new double[n];
        double[] y = new double[n];
        double[] yaw = new double[n];
        double time = -1e6;
        for (int i = 0; i < n; i++) {
            time = Math.nextUp(time) + (rnd.nextBoolean() ? 0 : rnd.nextDouble(1.0));
            t[i] = time;
            x[i] = anyPosition(rnd);
            y[i] = anyPosition(rnd);
            yaw[i] = anyFinite(rnd);
        }
        PlanarTrajectory written = PlanarTrajectory.of(t.clone(), x.clone(), y.clone(), yaw.clone());
        Path file = dir.resolve("out.csv");
        TrajectoryWriter.write(written, file);
        PlanarTrajectory read = (PlanarTrajectory) TrajectoryReader.read(file, ReadOptions.defaults()).trajectory();
        assertEquals(n, read.size());
        for (int i = 0; i < n; i++) {
            assertBits(t[i], read.t(i));
            assertBits(x[i], read.x(i));
            assertBits(y[i], read.y(i));
            assertBits(yaw[i], read.yaw(i));
        }
    }

    @Test
    void spatialTumRoundTripIsBitExact(@TempDir Path dir) throws IOException {
        SplittableRandom rnd = new SplittableRandom(5);
        int n = 20_000;
        double[][] c = new double[8][n];
        for (int i = 0; i < n; i++) {
            c[0][i] = 1.3e9 + 0.01 * i + rnd.nextDouble(0.001);
            for (int k = 1; k < 4; k++) {
                c[k][i] = anyPosition(rnd);
            }
            double norm = 0;
            for (int k = 4; k < 8; k++) {
                c[k][i] = rnd.nextDouble(-1, 1);
                norm += c[k][i] * c[k][i];
            }
            for (int k = 4; k < 8; k++) {
                c[k][i] /= Math.sqrt(norm); // unit within rounding, as the reader requires
            }
        }
        SpatialTrajectory written = SpatialTrajectory.of(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]);
        Path file = dir.resolve("out.tum");
        TrajectoryWriter.write(written, file);
        SpatialTrajectory read = (SpatialTrajectory) TrajectoryReader.read(file, ReadOptions.defaults()).trajectory();
        assertEquals(n, read.size());
        for (int i = 0; i < n; i++) {
            assertBits(written.t(i), read.t(i));
            assertBits(written.x(i), read.x(i));
            assertBits(written.y(i), read.y(i));
            assertBits(written.z(i), read.z(i));
            assertBits(written.qw(i), read.qw(i));
            assertBits(written.qx(i), read.qx(i));
            assertBits(written.qy(i), read.qy(i));
            assertBits(written.qz(i), read.qz(i));
        }
    }

    @Test
    void csvAndTumLayoutsAreTheDocumentedOnes() throws IOException {
        StringWriter csv = new StringWriter();
        TrajectoryWriter.writeCsv(PlanarTrajectory.of(new double[] {0.5}, new double[] {1.0}, new double[] {-2.0},
                new double[] {0.25}), csv);
        assertEquals("t,x,y,yaw\n0.5,1.0,-2.0,0.25\n", csv.toString());
        StringWriter tum = new StringWriter();
        // quaternion (w, x, y, z) = (0, 0, 0, 1) is written with w last
        TrajectoryWriter.writeTum(SpatialTrajectory.of(new double[] {1.5}, new double[] {1}, new double[] {2},
                new double[] {3}, new double[] {0}, new double[] {0}, new double[] {0}, new double[] {1}), tum);
        assertEquals("# timestamp tx ty tz qx qy qz qw\n1.5 1.0 2.0 3.0 0.0 0.0 1.0 0.0\n", tum.toString());
    }

    private static void assertBits(double expected, double actual) {
        assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual),
                expected + " vs " + actual);
    }
}
