package org.trajeval.core.io;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.SpatialTrajectory;
import org.trajeval.core.traj.Trajectory;

/**
 * Writes trajectories in the formats {@link TrajectoryReader} reads: a planar trajectory as CSV
 * {@code t,x,y,yaw} (s, m, m, rad), a spatial one as TUM {@code t tx ty tz qx qy qz qw}. Every
 * number is written with {@link Double#toString(double)}, which reads back to the same double,
 * so reading a written file gives bit-identical columns.
 */
public final class TrajectoryWriter {
    /** Header row of the planar CSV. */
    public static final String CSV_HEADER = "t,x,y,yaw";
    /** Comment line opening a TUM file. */
    public static final String TUM_HEADER = "# timestamp tx ty tz qx qy qz qw";

    private TrajectoryWriter() {
    }

    /**
     * Writes a trajectory to a file (UTF-8, created or replaced): planar as CSV, spatial as TUM.
     *
     * @throws IOException if the file cannot be written
     */
    public static void write(Trajectory trajectory, Path path) throws IOException {
        try (Writer w = new BufferedWriter(Files.newBufferedWriter(path, StandardCharsets.UTF_8), 1 << 16)) {
            if (trajectory instanceof PlanarTrajectory p) {
                writeCsv(p, w);
            } else if (trajectory instanceof SpatialTrajectory s) {
                writeTum(s, w);
            }
        }
    }

    /** Writes {@code t,x,y,yaw} and one line per pose; the caller closes the writer. */
    public static void writeCsv(PlanarTrajectory trajectory, Writer out) throws IOException {
        StringBuilder sb = new StringBuilder(96);
        out.write(CSV_HEADER);
        out.write('\n');
        for (int i = 0; i < trajectory.size(); i++) {
            sb.setLength(0);
            sb.append(trajectory.t(i)).append(',').append(trajectory.x(i)).append(',')
                    .append(trajectory.y(i)).append(',').append(trajectory.yaw(i)).append('\n');
            out.append(sb);
        }
        out.flush();
    }

    /** Writes a {@code #} header and one TUM line per pose (quaternion with w last); the caller closes the writer. */
    public static void writeTum(SpatialTrajectory trajectory, Writer out) throws IOException {
        StringBuilder sb = new StringBuilder(192);
        out.write(TUM_HEADER);
        out.write('\n');
        for (int i = 0; i < trajectory.size(); i++) {
            sb.setLength(0);
            sb.append(trajectory.t(i)).append(' ').append(trajectory.x(i)).append(' ').append(trajectory.y(i))
                    .append(' ').append(trajectory.z(i)).append(' ').append(trajectory.qx(i)).append(' ')
                    .append(trajectory.qy(i)).append(' ').append(trajectory.qz(i)).append(' ')
                    .append(trajectory.qw(i)).append('\n');
            out.append(sb);
        }
        out.flush();
    }

    /**
     * Writes KITTI poses: per pose the first three rows of the 4x4 pose matrix, row-major
     * ({@code r11 r12 r13 tx r21 r22 r23 ty r31 r32 r33 tz}); no stamps. The caller closes the writer.
     */
    public static void writeKitti(SpatialTrajectory trajectory, Writer out) throws IOException {
        StringBuilder sb = new StringBuilder(256);
        org.trajeval.core.traj.PoseSequence p = trajectory.poses();
        for (int i = 0; i < trajectory.size(); i++) {
            sb.setLength(0);
            double[] t = {p.x(i), p.y(i), p.z(i)};
            for (int row = 0; row < 3; row++) {
                for (int col = 0; col < 3; col++) {
                    sb.append(p.r(i, row, col)).append(' ');
                }
                sb.append(t[row]).append(row == 2 ? '\n' : ' ');
            }
            out.append(sb);
        }
        out.flush();
    }
}
