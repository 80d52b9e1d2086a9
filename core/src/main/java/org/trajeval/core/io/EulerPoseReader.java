package org.trajeval.core.io;

import java.util.ArrayList;
import java.util.List;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Pose files that give the attitude as Euler angles, roll, pitch, yaw (rad), with
 * R = Rz(yaw) Ry(pitch) Rx(roll) (rotations about the fixed x, then y, then z axis), as the NCLT
 * and Oxford RobotCar software define them. Worked example: roll = pitch = 0, yaw = pi/2 turns the
 * body's x axis onto the frame's y axis; as a quaternion (w, x, y, z) = (cos pi/4, 0, 0, sin pi/4).
 * <ul>
 * <li>{@link TrajectoryFormat#NCLT}: {@code utime,x,y,z,roll,pitch,yaw} per line, no header, utime in
 *     microseconds (the ground truth {@code groundtruth_DATE.csv} and the odometry
 *     {@code odometry_mu_100hz.csv} of the NCLT dataset).</li>
 * <li>{@link TrajectoryFormat#ROBOTCAR_INS}: the INS file {@code gps/ins.csv}, header
 *     {@code timestamp,ins_status,latitude,longitude,altitude,northing,easting,down,utm_zone,...,roll,
 *     pitch,yaw}, timestamp in microseconds; the position is (northing, easting, down) (m), NED.</li>
 * <li>{@link TrajectoryFormat#ROBOTCAR_VO}: the visual odometry {@code vo/vo.csv}, header
 *     {@code source_timestamp,destination_timestamp,x,y,z,roll,pitch,yaw}: each row a relative pose,
 *     chained as the dataset's SDK chains them (its {@code interpolate_vo_poses}): the pose at a row's
 *     source_timestamp is the previous pose times T(x, y, z, roll, pitch, yaw), starting from the
 *     identity at the first row's destination_timestamp.</li>
 * </ul>
 */
final class EulerPoseReader {
    private EulerPoseReader() {
    }

    /** Where a format's fields are. */
    private record Layout(String[] header, int[] fields, String[] names, String[] units, boolean relative) {
    }

    private static final String[] POSE_NAMES = {"utime", "x", "y", "z", "roll", "pitch", "yaw"};
    private static final String[] POSE_UNITS = {"(us)", "(m)", "(m)", "(m)", "(rad)", "(rad)", "(rad)"};

    private static Layout layout(TrajectoryFormat f) {
        return switch (f) {
            case NCLT -> new Layout(null, new int[] {0, 1, 2, 3, 4, 5, 6}, POSE_NAMES, POSE_UNITS, false);
            case ROBOTCAR_INS -> new Layout(new String[] {"timestamp", "northing", "easting", "down", "roll", "pitch",
                "yaw"}, null, new String[] {"timestamp", "northing", "easting", "down", "roll", "pitch", "yaw"},
                    POSE_UNITS, false);
            case ROBOTCAR_VO -> new Layout(new String[] {"source_timestamp", "x", "y", "z", "roll", "pitch", "yaw",
                "destination_timestamp"}, null, new String[] {"source_timestamp", "x", "y", "z", "roll", "pitch", "yaw",
                    "destination_timestamp"}, new String[] {"(us)", "(m)", "(m)", "(m)", "(rad)", "(rad)", "(rad)",
                    "(us)"}, true);
            default -> throw new IllegalArgumentException("not an Euler-angle format: " + f);
        };
    }

    static LoadedTrajectory read(ByteSource file, String source, ReadOptions options, String reason, TrajectoryFormat f) {
        Layout l = layout(f);
        try (ByteLines lines = ByteLines.open(file, source, options.maxBytes())) {
            NumericRows rows = new NumericRows(lines, source, (byte) ',', false);
            int[] fields = l.fields();
            if (l.header() != null) {
                fields = header(rows, source, l.header(), f);
            } else {
                rows.requireFields(7, "utime, x, y, z, roll, pitch, yaw (NCLT: us, m, m, m, rad, rad, rad)");
            }
            rows.select(fields, l.names(), l.units());
            PoseBuffer poses = new PoseBuffer(source, l.names()[0], 8, options.order(), options.duplicates(),
                    options.maxPoses()).positions(l.names()[1], l.names()[2], l.names()[3]);
            poses.sizeFrom(lines);
            double[] in = new double[fields.length];
            double[] row = new double[8];
            double[] q = new double[4];
            double[] pose = {0, 0, 0, 1, 0, 0, 0}; // x y z qw qx qy qz of the chained pose
            boolean first = true;
            while (rows.next(in)) {
                long line = rows.lineNumber();
                for (int k : new int[] {0, fields.length == 8 ? 7 : 0}) {
                    if (in[k] != Math.rint(in[k])) {
                        throw new InputException(source, line, l.names()[k], InputProblem.SUSPICIOUS_TIME_UNIT,
                                "column '" + l.names()[k] + "' must be a whole number of microseconds (us)",
                                rows.selectedText(k));
                    }
                }
                euler(in[4], in[5], in[6], q);
                if (l.relative()) {
                    if (first) {
                        // the identity at the first row's destination_timestamp
                        row[0] = in[7] / 1e6;
                        set(row, pose);
                        add(poses, row, line, rows, 7);
                        first = false;
                    }
                    chain(pose, in[1], in[2], in[3], q);
                    row[0] = in[0] / 1e6;
                    set(row, pose);
                } else {
                    row[0] = in[0] / 1e6;
                    row[1] = in[1];
                    row[2] = in[2];
                    row[3] = in[3];
                    System.arraycopy(q, 0, row, 4, 4);
                }
                add(poses, row, line, rows, 0);
            }
            // handed over as filled (up to 4 % longer than the pose count), not trimmed by a copy
            double[][] c = poses.finishUntrimmed("it holds no pose line");
            String sha = lines.finishSha256();
            return new LoadedTrajectory(source, f, reason,
                    SpatialTrajectory.ofFirst(poses.size(), c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]), sha,
                    false);
        }
    }

    private static void add(PoseBuffer poses, double[] row, long line, NumericRows rows, int timeField) {
        int code = poses.add(row, line);
        if (code != PoseBuffer.ACCEPTED) {
            throw poses.orderProblem(code, row[0], line, rows.selectedText(timeField));
        }
    }

    private static void set(double[] row, double[] pose) {
        System.arraycopy(pose, 0, row, 1, 7);
    }

    /** Reads the header line and returns the field index of each wanted column, refusing a missing one. */
    private static int[] header(NumericRows rows, String source, String[] wanted, TrajectoryFormat f) {
        if (!rows.nextContentLine()) {
            throw FileProblems.empty(source, "it holds no header line");
        }
        List<String> names = new ArrayList<>();
        for (int i = 0; i < rows.fieldCount(); i++) {
            names.add(rows.field(i).trim());
        }
        int[] out = new int[wanted.length];
        for (int k = 0; k < wanted.length; k++) {
            out[k] = names.indexOf(wanted[k]);
            if (out[k] < 0) {
                throw new InputException(source, rows.lineNumber(), wanted[k], InputProblem.MISSING_COLUMN,
                        "the " + f.id() + " header needs a column '" + wanted[k] + "' (" + String.join(",", wanted)
                                + ")", rows.lineText());
            }
        }
        rows.requireFields(names.size(), names.size() + " fields as the header");
        return out;
    }

    /**
     * The unit quaternion (w, x, y, z) of R = Rz(yaw) Ry(pitch) Rx(roll): q = qz(yaw) qy(pitch) qx(roll),
     * each q_a(t) = (cos t/2, sin t/2 along axis a).
     */
    static void euler(double roll, double pitch, double yaw, double[] q) {
        double cr = Math.cos(roll / 2);
        double sr = Math.sin(roll / 2);
        double cp = Math.cos(pitch / 2);
        double sp = Math.sin(pitch / 2);
        double cy = Math.cos(yaw / 2);
        double sy = Math.sin(yaw / 2);
        q[0] = cy * cp * cr + sy * sp * sr;
        q[1] = cy * cp * sr - sy * sp * cr;
        q[2] = cy * sp * cr + sy * cp * sr;
        q[3] = sy * cp * cr - cy * sp * sr;
    }

    /** pose := pose * T(t, q): position p + R(pose) t, attitude q(pose) q, renormalised. */
    private static void chain(double[] pose, double tx, double ty, double tz, double[] q) {
        double w = pose[3];
        double x = pose[4];
        double y = pose[5];
        double z = pose[6];
        // rotate t by the current attitude: t' = q t q*
        double ix = w * tx + y * tz - z * ty;
        double iy = w * ty + z * tx - x * tz;
        double iz = w * tz + x * ty - y * tx;
        double iw = -x * tx - y * ty - z * tz;
        pose[0] += ix * w - iw * x - iy * z + iz * y;
        pose[1] += iy * w - iw * y - iz * x + ix * z;
        pose[2] += iz * w - iw * z - ix * y + iy * x;
        double nw = w * q[0] - x * q[1] - y * q[2] - z * q[3];
        double nx = w * q[1] + x * q[0] + y * q[3] - z * q[2];
        double ny = w * q[2] - x * q[3] + y * q[0] + z * q[1];
        double nz = w * q[3] + x * q[2] - y * q[1] + z * q[0];
        double n = Math.sqrt(nw * nw + nx * nx + ny * ny + nz * nz);
        pose[3] = nw / n;
        pose[4] = nx / n;
        pose[5] = ny / n;
        pose[6] = nz / n;
    }
}
