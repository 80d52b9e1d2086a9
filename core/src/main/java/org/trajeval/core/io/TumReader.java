package org.trajeval.core.io;

import org.trajeval.core.traj.SpatialTrajectory;

/**
 * TUM RGB-D: {@code t tx ty tz qx qy qz qw} per line (s, m, unit quaternion with w last),
 * separated by spaces or tabs; {@code #} comment lines and blank lines skipped. Numbers read as
 * evo reads them ({@code np.loadtxt}, i.e. the double nearest to the decimal text).
 */
final class TumReader {
    private static final String[] NAMES = {"t", "tx", "ty", "tz", "qx", "qy", "qz", "qw"};
    private static final String[] UNITS = {"(s)", "(m)", "(m)", "(m)", "", "", "", ""};
    private static final String TIME_UNIT_REMEDY = "convert them to seconds (TUM stamps are seconds), "
            + "or write a CSV and pass --time-unit %s";

    private TumReader() {
    }

    static LoadedTrajectory read(ByteSource file, String source, ReadOptions options, String reason) {
        try (ByteLines lines = ByteLines.open(file, source, options.maxBytes())) {
            NumericRows rows = new NumericRows(lines, source, NumericRows.WHITESPACE, false);
            rows.select(new int[] {0, 1, 2, 3, 4, 5, 6, 7}, NAMES, UNITS);
            rows.requireFields(8, "t tx ty tz qx qy qz qw, separated by spaces");
            PoseBuffer poses = new PoseBuffer(source, "t", 8, options.order(),
                    options.duplicates(), options.maxPoses()).positions("tx", "ty", "tz");
            poses.sizeFrom(lines);
            double[] in = new double[8];
            double[] row = new double[8];
            double tolerance = options.quaternionTolerance();
            while (readBatch(rows, poses, in, row, tolerance, source)) {
                // batches: compiled early as a whole method (see CsvTrajectoryReader.readBatch)
            }
            double[][] c = poses.finishUntrimmed("it holds only comment or blank lines");
            String sha = lines.finishSha256();
            return new LoadedTrajectory(source, TrajectoryFormat.TUM, reason,
                    SpatialTrajectory.ofFirst(poses.size(), c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]), sha, false);
        }
    }

    /** Reads up to 4096 poses; @return false at the end of the file. */
    private static boolean readBatch(NumericRows rows, PoseBuffer poses, double[] in, double[] row, double tolerance,
            String source) {
        for (int k = 0; k < 4096; k++) {
            if (!rows.next(in)) {
                return false;
            }
            long line = rows.lineNumber();
            if (TimeUnitCheck.implausible(in[0])) {
                throw TimeUnitCheck.refuse(source, line, "t", in[0], TimeUnit.S, TIME_UNIT_REMEDY,
                        rows.selectedText(0));
            }
            // file order qx qy qz qw -> stored order qw qx qy qz
            if (!(QuaternionCheck.normError(in[7], in[4], in[5], in[6]) <= tolerance)) {
                throw QuaternionCheck.refuse(source, line, "qx qy qz qw", in[7], in[4], in[5], in[6], tolerance,
                        rows.selectedText(4) + " " + rows.selectedText(5) + " " + rows.selectedText(6) + " "
                                + rows.selectedText(7));
            }
            row[0] = in[0];
            row[1] = in[1];
            row[2] = in[2];
            row[3] = in[3];
            row[4] = in[7];
            row[5] = in[4];
            row[6] = in[5];
            row[7] = in[6];
            int code = poses.add(row, line);
            if (code != PoseBuffer.ACCEPTED) {
                throw poses.orderProblem(code, row[0], line, rows.selectedText(0));
            }
        }
        return true;
    }
}
