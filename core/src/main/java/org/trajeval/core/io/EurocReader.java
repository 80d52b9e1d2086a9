package org.trajeval.core.io;

import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * EuRoC MAV ground truth: comma-separated, {@code #} header, fields {@code timestamp [ns], p_x,
 * p_y, p_z [m], q_w, q_x, q_y, q_z} (w first) followed by any number of further columns, which
 * are ignored. The stamp is converted as evo does ({@code np.loadtxt} then
 * {@code np.divide(stamps, 1e9)}): parsed as the nearest double, then divided by 1e9, which is
 * bit-for-bit the same time (s) as evo's.
 */
final class EurocReader {
    private static final String[] NAMES = {"timestamp", "p_x", "p_y", "p_z", "q_w", "q_x", "q_y", "q_z"};
    private static final String[] UNITS = {"(ns)", "(m)", "(m)", "(m)", "", "", "", ""};

    private EurocReader() {
    }

    static LoadedTrajectory read(ByteSource file, String source, ReadOptions options, String reason) {
        try (ByteLines lines = ByteLines.open(file, source, options.maxBytes())) {
            NumericRows rows = new NumericRows(lines, source, (byte) ',', false);
            rows.select(new int[] {0, 1, 2, 3, 4, 5, 6, 7}, NAMES, UNITS);
            rows.requireAtLeastFields(8, "timestamp [ns], p_x, p_y, p_z [m], q_w, q_x, q_y, q_z, ...");
            PoseBuffer poses = new PoseBuffer(source, "timestamp", 8, options.order(),
                    options.duplicates(), options.maxPoses()).positions("p_x", "p_y", "p_z");
            poses.sizeFrom(lines);
            double[] row = new double[8];
            double tolerance = options.quaternionTolerance();
            while (rows.next(row)) {
                long line = rows.lineNumber();
                double stamp = row[0];
                if (stamp != Math.rint(stamp)) {
                    throw new InputException(source, line, "timestamp", InputProblem.SUSPICIOUS_TIME_UNIT,
                            "column 'timestamp' must be an integer number of nanoseconds (ns)"
                                    + (Math.abs(stamp) < TimeUnitCheck.MAX_PLAUSIBLE_S
                                            ? "; this looks like seconds (s): write nanoseconds, or convert the file"
                                                    + " to TUM (stamps in s)"
                                            : ""),
                            rows.selectedText(0));
                }
                row[0] = stamp / 1e9;
                if (!(QuaternionCheck.normError(row[4], row[5], row[6], row[7]) <= tolerance)) {
                    throw QuaternionCheck.refuse(source, line, "q_w q_x q_y q_z", row[4], row[5], row[6], row[7],
                            tolerance, rows.selectedText(4) + "," + rows.selectedText(5) + ","
                                    + rows.selectedText(6) + "," + rows.selectedText(7));
                }
                int code = poses.add(row, line);
                if (code != PoseBuffer.ACCEPTED) {
                    throw poses.orderProblem(code, row[0], line, rows.selectedText(0));
                }
            }
            double[][] c = poses.finishUntrimmed("it holds only comment or blank lines");
            String sha = lines.finishSha256();
            return new LoadedTrajectory(source, TrajectoryFormat.EUROC, reason,
                    SpatialTrajectory.ofFirst(poses.size(), c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]), sha, false);
        }
    }
}
