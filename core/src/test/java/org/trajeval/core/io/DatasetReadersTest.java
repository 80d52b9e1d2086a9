package org.trajeval.core.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.protocol.RunEngine;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * NCLT, RobotCar (INS, VO) and ICL-NUIM files written from known poses, after the formats' published
 * descriptions (the NCLT paper's ground-truth and odometry CSV; the RobotCar SDK's
 * interpolate_poses.py and transform.py: columns, microseconds, R = Rz(yaw) Ry(pitch) Rx(roll), VO
 * chained abs = abs * T(row)), read and scored against the same poses written as TUM.
 */
class DatasetReadersTest {
    private static final double TOL = 1e-12;
    @TempDir
    Path dir;

    /** Rotation matrix Rz(y) Ry(p) Rx(r) built as a product of the three elementary matrices. */
    private static double[][] zyx(double r, double p, double y) {
        double[][] rx = {{1, 0, 0}, {0, Math.cos(r), -Math.sin(r)}, {0, Math.sin(r), Math.cos(r)}};
        double[][] ry = {{Math.cos(p), 0, Math.sin(p)}, {0, 1, 0}, {-Math.sin(p), 0, Math.cos(p)}};
        double[][] rz = {{Math.cos(y), -Math.sin(y), 0}, {Math.sin(y), Math.cos(y), 0}, {0, 0, 1}};
        return mul(rz, mul(ry, rx));
    }

    private static double[][] mul(double[][] a, double[][] b) {
        double[][] c = new double[3][3];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                for (int k = 0; k < 3; k++) {
                    c[i][j] += a[i][k] * b[k][j];
                }
            }
        }
        return c;
    }

    /** Quaternion (w, x, y, z) of a rotation matrix (Shepperd's method, largest diagonal term). */
    private static double[] quaternion(double[][] m) {
        double tr = m[0][0] + m[1][1] + m[2][2];
        if (tr > 0) {
            double s = Math.sqrt(tr + 1.0) * 2;
            return new double[] {0.25 * s, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s};
        } else if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
            double s = Math.sqrt(1.0 + m[0][0] - m[1][1] - m[2][2]) * 2;
            return new double[] {(m[2][1] - m[1][2]) / s, 0.25 * s, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s};
        } else if (m[1][1] > m[2][2]) {
            double s = Math.sqrt(1.0 + m[1][1] - m[0][0] - m[2][2]) * 2;
            return new double[] {(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, 0.25 * s, (m[1][2] + m[2][1]) / s};
        }
        double s = Math.sqrt(1.0 + m[2][2] - m[0][0] - m[1][1]) * 2;
        return new double[] {(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, 0.25 * s};
    }

    private static LoadedTrajectory read(Path file, TrajectoryFormat f) {
        return TrajectoryReader.read(file, f == null ? ReadOptions.defaults() : ReadOptions.defaults().withFormat(f));
    }

    /** 200 poses 0.1 s apart from utime 1326030975000000 us (an NCLT session start), seeded. */
    private static double[][] poses(long seed) {
        SplittableRandom rng = new SplittableRandom(seed);
        double[][] p = new double[7][200];
        for (int i = 0; i < 200; i++) {
            p[0][i] = 1326030975000000L + 100000L * i;
            p[1][i] = 0.5 * i + rng.nextGaussian() * 0.01;
            p[2][i] = Math.sin(0.05 * i) * 3;
            p[3][i] = 0.1 * rng.nextGaussian();
            p[4][i] = 0.05 * rng.nextGaussian();
            p[5][i] = 0.05 * rng.nextGaussian();
            p[6][i] = -3.0 + 0.03 * i;
        }
        return p;
    }

    private Path tum(String name, double[][] p) throws IOException {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < p[0].length; i++) {
            double[] q = quaternion(zyx(p[4][i], p[5][i], p[6][i]));
            sb.append(Double.toString(p[0][i] / 1e6)).append(' ').append(p[1][i]).append(' ').append(p[2][i]).append(' ')
                    .append(p[3][i]).append(' ').append(q[1]).append(' ').append(q[2]).append(' ').append(q[3])
                    .append(' ').append(q[0]).append('\n');
        }
        return Files.writeString(dir.resolve(name), sb.toString());
    }

    private Path nclt(String name, double[][] p) throws IOException {
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < p[0].length; i++) {
            sb.append((long) p[0][i]);
            for (int k = 1; k < 7; k++) {
                sb.append(',').append(p[k][i]);
            }
            sb.append('\n');
        }
        return Files.writeString(dir.resolve(name), sb.toString());
    }

    private static EvaluationReport score(LoadedTrajectory ref, LoadedTrajectory est) {
        EvaluationOptions o = SettingsResolver.evaluationOptions(SettingValues.of(List.of(), null), DataKind.SPATIAL);
        return RunEngine.standard().evaluate(ref, est, o);
    }

    @Test
    void eulerAnglesAreZyxAsTheDatasetsDefineThem() {
        double[] q = new double[4];
        // yaw pi/2 alone: a rotation of pi/2 about z, (cos pi/4, 0, 0, sin pi/4)
        EulerPoseReader.euler(0, 0, Math.PI / 2, q);
        assertEquals(Math.cos(Math.PI / 4), q[0], TOL);
        assertEquals(Math.sin(Math.PI / 4), q[3], TOL);
        // any angles: the quaternion of the product Rz Ry Rx (up to sign)
        EulerPoseReader.euler(0.3, -0.2, 2.5, q);
        double[] m = quaternion(zyx(0.3, -0.2, 2.5));
        double sign = Math.signum(q[0] * m[0] + q[1] * m[1] + q[2] * m[2] + q[3] * m[3]);
        for (int k = 0; k < 4; k++) {
            assertEquals(m[k], sign * q[k], TOL);
        }
    }

    @Test
    void ncltFilesScoreExactlyAsTheSamePosesInTum() throws IOException {
        double[][] truth = poses(1);
        double[][] estimate = poses(2);
        LoadedTrajectory refTum = read(tum("gt.tum", truth), null);
        LoadedTrajectory refNclt = read(nclt("groundtruth_2012-01-08.csv", truth), TrajectoryFormat.NCLT);
        LoadedTrajectory est = read(tum("est.tum", estimate), null);
        LoadedTrajectory estNclt = read(nclt("odometry_mu_100hz.csv", estimate), TrajectoryFormat.NCLT);
        assertEquals(TrajectoryFormat.NCLT, refNclt.format());
        // time: utime (us) / 1e6 is the TUM stamp, bit for bit
        assertEquals(refTum.trajectory().t(7), refNclt.trajectory().t(7), 0.0);
        EvaluationReport a = score(refTum, est);
        EvaluationReport b = score(refNclt, estNclt);
        assertEquals(a.ate().transM().rmse(), b.ate().transM().rmse(), TOL);
        assertEquals(a.ate().rotRad().rmse(), b.ate().rotRad().rmse(), TOL);
        assertEquals(a.rpe().transM().rmse(), b.rpe().transM().rmse(), TOL);
        // and the truth against itself in the two formats: nothing to find
        assertEquals(0.0, score(refTum, refNclt).ate().transM().rmse(), 1e-9);
    }

    @Test
    void robotCarInsIsDetectedByItsHeaderAndReadAsNorthingEastingDown() throws IOException {
        double[][] truth = poses(3);
        StringBuilder sb = new StringBuilder("timestamp,ins_status,latitude,longitude,altitude,northing,easting,down,"
                + "utm_zone,velocity_north,velocity_east,velocity_down,roll,pitch,yaw\n");
        for (int i = 0; i < truth[0].length; i++) {
            sb.append(String.format(Locale.ROOT, "%d,INS_SOLUTION_GOOD,51.76,-1.26,110.0,%s,%s,%s,30U,0.1,0.2,0.0,%s,%s,"
                    + "%s%n", (long) truth[0][i], truth[1][i], truth[2][i], truth[3][i], truth[4][i], truth[5][i],
                    truth[6][i]));
        }
        LoadedTrajectory ins = read(Files.writeString(dir.resolve("ins.csv"), sb.toString()), null);
        assertEquals(TrajectoryFormat.ROBOTCAR_INS, ins.format());
        assertTrue(ins.formatReason().contains("RobotCar INS"), ins.formatReason());
        LoadedTrajectory tum = read(tum("ins.tum", truth), null);
        assertEquals(0.0, score(tum, ins).ate().transM().rmse(), 1e-9);
        SpatialTrajectory s = (SpatialTrajectory) ins.trajectory();
        assertEquals(truth[1][5], s.x(5), 0.0);
    }

    @Test
    void robotCarVoIsChainedAsTheSdkChainsIt() throws IOException {
        // four relative poses "1 m forward, then turn +90 deg about z": a unit square back to the start
        // (by hand: (1,0) heading 90, (1,1) heading 180, (0,1) heading 270, (0,0) heading 360)
        StringBuilder sb = new StringBuilder("source_timestamp,destination_timestamp,x,y,z,roll,pitch,yaw\n");
        for (int i = 1; i <= 4; i++) {
            sb.append(1_000_000L * (i + 1)).append(',').append(1_000_000L * i).append(",1,0,0,0,0,")
                    .append(Math.PI / 2).append('\n');
        }
        LoadedTrajectory vo = read(Files.writeString(dir.resolve("vo.csv"), sb.toString()), null);
        assertEquals(TrajectoryFormat.ROBOTCAR_VO, vo.format());
        SpatialTrajectory s = (SpatialTrajectory) vo.trajectory();
        assertEquals(5, s.size());
        assertEquals(1.0, s.t(0), 0.0); // the identity at the first destination_timestamp
        double[][] xy = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
        for (int i = 0; i < 5; i++) {
            assertEquals(xy[i][0], s.x(i), TOL);
            assertEquals(xy[i][1], s.y(i), TOL);
        }
        // heading after two turns is 180 deg: q = (0, 0, 0, +-1)
        assertEquals(1.0, Math.abs(s.qz(2)), TOL);
    }

    @Test
    void iclNuimFramesAreIndexStamps() throws IOException {
        Path f = Files.writeString(dir.resolve("livingRoom0.gt.freiburg"),
                "0 0 0 -2.25 0 0 0 1\n1 0.01 0 -2.25 0 0 0 1\n2 0.02 0 -2.25 0 0 0 1\n");
        LoadedTrajectory t = read(f, null);
        assertEquals(TrajectoryFormat.ICL_NUIM, t.format());
        assertTrue(t.indexTimestamps());
        Path bad = Files.writeString(dir.resolve("bad.gt.freiburg"), "0.5 0 0 0 0 0 0 1\n1.5 0 0 0 0 0 0 1\n");
        InputException e = assertThrows(InputException.class, () -> read(bad, null));
        assertEquals(InputProblem.NOT_A_NUMBER, e.problem());
    }

    @Test
    void ncltRowsThatAreNotSevenNumbersAreRefusedWithTheLine() throws IOException {
        Path f = Files.writeString(dir.resolve("gt.csv"), "1326030975000000,1,2,3,0,0,0\n1326030975100000,1,2,3,0,0\n");
        InputException e = assertThrows(InputException.class, () -> read(f, TrajectoryFormat.NCLT));
        assertEquals(2, e.line());
        Path g = Files.writeString(dir.resolve("gt2.csv"), "1326030975.5,1,2,3,0,0,0\n");
        e = assertThrows(InputException.class, () -> read(g, TrajectoryFormat.NCLT));
        assertEquals(InputProblem.SUSPICIOUS_TIME_UNIT, e.problem());
        Path h = Files.writeString(dir.resolve("ins.csv"), "timestamp,ins_status,northing,easting\n1,G,2,3\n");
        e = assertThrows(InputException.class, () -> read(h, null));
        assertEquals(InputProblem.MISSING_COLUMN, e.problem());
        assertEquals("down", e.column());
    }
}
