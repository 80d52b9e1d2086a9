package org.trajeval.core.io;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * KITTI odometry poses: 12 numbers per line, the 3x4 matrix [R|t] row-major
 * ({@code r11 r12 r13 tx r21 r22 r23 ty r31 r32 r33 tz}, t in m). The file has no stamps: pose
 * i gets t = i s and {@link LoadedTrajectory#indexTimestamps()} is true, unless a times file
 * (one time in s per line, as many lines as poses) gives real stamps. R must be a rotation
 * within the tolerance (max |R^T R - I| and |det R - 1|; the KITTI ground truth, written with 7
 * digits, is orthonormal to about 1e-6) and is kept exactly as read, as evo keeps it
 * ({@link SpatialTrajectory#ofMatrices}).
 */
final class KittiReader {
    private static final String[] NAMES = {"r11", "r12", "r13", "tx", "r21", "r22", "r23", "ty", "r31", "r32", "r33",
        "tz"};
    private static final String[] UNITS = {"", "", "", "(m)", "", "", "", "(m)", "", "", "", "(m)"};
    /** Pose-buffer columns: t, x, y, z, then R row-major (9). */
    private static final int COLUMNS = 13;
    private static final String TIME_UNIT_REMEDY = "convert the times file to seconds (KITTI times are seconds)";

    private KittiReader() {
    }

    static LoadedTrajectory read(ByteSource file, String source, ReadOptions options, String reason) {
        double[][] c;
        int n;
        String sha;
        try (ByteLines lines = ByteLines.open(file, source, options.maxBytes())) {
            NumericRows rows = new NumericRows(lines, source, NumericRows.WHITESPACE, false);
            rows.select(new int[] {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, NAMES, UNITS);
            rows.requireFields(12, "r11 r12 r13 tx r21 r22 r23 ty r31 r32 r33 tz, separated by spaces");
            PoseBuffer poses = new PoseBuffer(source, "index", COLUMNS, TimestampOrder.REFUSE_UNSORTED,
                    options.maxPoses()).positions("tx", "ty", "tz");
            poses.sizeFrom(lines);
            double[] in = new double[12];
            double[] r = new double[9];
            double[] row = new double[COLUMNS];
            double tolerance = options.quaternionTolerance();
            while (rows.next(in)) {
                for (int i = 0; i < 3; i++) {
                    r[3 * i] = in[4 * i];
                    r[3 * i + 1] = in[4 * i + 1];
                    r[3 * i + 2] = in[4 * i + 2];
                }
                double orthoError = RotationMatrix.orthonormalityError(r);
                double det = RotationMatrix.determinant(r);
                if (!(orthoError <= tolerance) || !(Math.abs(det - 1.0) <= tolerance)) {
                    throw new InputException(source, rows.lineNumber(), "r11..r33", InputProblem.NOT_A_ROTATION,
                            String.format(Locale.ROOT, "the 3x3 part (r11..r33) must be a rotation within %s "
                                    + "(max |R^T R - I| = %.3g, det R = %.6g)", tolerance, orthoError, det),
                            rows.lineText());
                }
                row[0] = poses.size();
                row[1] = in[3];
                row[2] = in[7];
                row[3] = in[11];
                System.arraycopy(r, 0, row, 4, 9);
                poses.add(row, rows.lineNumber());
            }
            // the columns as filled (up to 4 % longer than the pose count): each value is copied once
            // more below, into the matrices or the times file's columns, so a trimmed copy would be a third
            c = poses.finishUntrimmed("it holds only comment or blank lines");
            n = poses.size();
            sha = lines.finishSha256();
        }
        boolean indexStamps = options.kittiTimes() == null;
        if (!indexStamps) {
            c = withTimes(c, n, source, options);
            reason = reason + "; times from " + options.kittiTimes();
        }
        for (int k = 0; k < 4; k++) {
            c[k] = c[k].length == n ? c[k] : Arrays.copyOf(c[k], n);
        }
        double[] matrices = new double[9 * n];
        for (int i = 0; i < n; i++) {
            for (int k = 0; k < 9; k++) {
                matrices[9 * i + k] = c[4 + k][i];
            }
        }
        return new LoadedTrajectory(source, TrajectoryFormat.KITTI, reason,
                SpatialTrajectory.ofMatrices(c[0], c[1], c[2], c[3], matrices), sha, indexStamps);
    }

    /**
     * Replaces the index stamps of the first n poses of the columns c by the times file's, one line
     * per pose, with the order policy; the columns returned hold exactly n poses.
     */
    private static double[][] withTimes(double[][] c, int n, String poseSource, ReadOptions options) {
        Path timesPath = options.kittiTimes();
        String source = timesPath.toString();
        TrajectoryReader.checkFile(timesPath, source, options.maxBytes());
        try (ByteLines lines = ByteLines.open(timesPath, source, options.maxBytes())) {
            NumericRows rows = new NumericRows(lines, source, NumericRows.WHITESPACE, false);
            rows.select(new int[] {0}, new String[] {"time"}, new String[] {"(s)"});
            rows.requireFields(1, "one time in s per line");
            PoseBuffer poses = new PoseBuffer(source, "time", COLUMNS, options.order(), options.duplicates(),
                    options.maxPoses()).capacity(n);
            double[] in = new double[1];
            double[] row = new double[COLUMNS];
            int k = 0;
            while (rows.next(in)) {
                long line = rows.lineNumber();
                if (k >= n) {
                    throw countMismatch(source, line, poseSource, n, "this is time number " + (k + 1));
                }
                if (TimeUnitCheck.implausible(in[0])) {
                    throw TimeUnitCheck.refuse(source, line, "time", in[0], TimeUnit.S, TIME_UNIT_REMEDY,
                            rows.selectedText(0));
                }
                row[0] = in[0];
                for (int col = 1; col < COLUMNS; col++) {
                    row[col] = c[col][k];
                }
                int code = poses.add(row, line);
                if (code != PoseBuffer.ACCEPTED) {
                    throw poses.orderProblem(code, row[0], line, rows.selectedText(0));
                }
                k++;
            }
            if (k < n) {
                throw countMismatch(source, 0, poseSource, n, "it has only " + k);
            }
            return poses.finish("it holds only comment or blank lines");
        }
    }

    private static InputException countMismatch(String source, long line, String poseSource, int poses,
            String found) {
        return new InputException(source, line, "time", InputProblem.WRONG_FIELD_COUNT,
                "the KITTI times file must have one time (s) per pose, " + poses + " for " + poseSource + "; " + found,
                null);
    }
}
