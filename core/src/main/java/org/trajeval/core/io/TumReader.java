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

    /** As {@link #read(ByteSource, String, ReadOptions, String)}, a big file in blocks on {@code threads}. */
    static LoadedTrajectory read(ByteSource file, String source, ReadOptions options, String reason,
            ReadThreads threads) {
        if (options.order() == TimestampOrder.REFUSE_UNSORTED) {
            LoadedTrajectory t = BlockRead.read(file, source, options, new Blocks(source, options, reason), threads);
            if (t != null) {
                return t;
            }
        }
        return read(file, source, options, reason);
    }

    static LoadedTrajectory read(ByteSource file, String source, ReadOptions options, String reason) {
        try (ByteLines lines = ByteLines.open(file, source, options.maxBytes())) {
            NumericRows rows = rows(lines, source);
            PoseBuffer poses = new PoseBuffer(source, "t", 8, options.order(),
                    options.duplicates(), options.maxPoses()).positions("tx", "ty", "tz");
            poses.sizeFrom(lines);
            double[] in = new double[8];
            double tolerance = options.quaternionTolerance();
            while (readBatch(rows, poses, in, tolerance, source)) {
                // batches: compiled early as a whole method (see CsvTrajectoryReader.readBatch)
            }
            double[][] c = poses.finishUntrimmed("it holds only comment or blank lines");
            String sha = lines.finishSha256();
            return new LoadedTrajectory(source, TrajectoryFormat.TUM, reason,
                    SpatialTrajectory.ofFirst(poses.size(), c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]), sha, false);
        }
    }

    private static NumericRows rows(ByteLines lines, String source) {
        NumericRows rows = new NumericRows(lines, source, NumericRows.WHITESPACE, false);
        rows.select(new int[] {0, 1, 2, 3, 4, 5, 6, 7}, NAMES, UNITS);
        rows.requireFields(8, "t tx ty tz qx qy qz qw, separated by spaces");
        return rows;
    }

    /**
     * Reads up to 4096 poses, each line's numbers into {@code in} (file order), then checked and
     * stored straight into the columns, the quaternion moved from the file's {@code qx qy qz qw}
     * to the columns' {@code qw qx qy qz}; @return false at the end of the file.
     */
    static boolean readBatch(NumericRows rows, PoseBuffer poses, double[] in, double tolerance, String source) {
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
            poses.checkPositions(in, line);
            int i = poses.place(in[0], line);
            if (i < 0) {
                throw poses.orderProblem(-i, in[0], line, rows.selectedText(0));
            }
            double[][] c = poses.liveColumns();
            c[0][i] = in[0];
            c[1][i] = in[1];
            c[2][i] = in[2];
            c[3][i] = in[3];
            c[4][i] = in[7];
            c[5][i] = in[4];
            c[6][i] = in[5];
            c[7][i] = in[6];
        }
        return true;
    }

    /** The blocks of a TUM file: every block read alike. */
    static final class Blocks implements BlockRead.Format {
        private final String source;
        private final ReadOptions options;
        private final String reason;

        Blocks(String source, ReadOptions options, String reason) {
            this.source = source;
            this.options = options;
            this.reason = reason;
        }

        @Override
        public int columns() {
            return 8;
        }

        @Override
        public NumericRows first(ByteLines lines) {
            return rows(lines, source);
        }

        @Override
        public NumericRows later(ByteLines lines) {
            return rows(lines, source);
        }

        @Override
        public PoseBuffer segment() {
            return new PoseBuffer(source, "t", 8, TimestampOrder.REFUSE_UNSORTED, options.duplicates(),
                    options.maxPoses()).positions("tx", "ty", "tz");
        }

        @Override
        public boolean readBatch(NumericRows rows, PoseBuffer poses, double[] in, double[] row) {
            return TumReader.readBatch(rows, poses, in, options.quaternionTolerance(), source);
        }

        @Override
        public LoadedTrajectory result(int n, double[][] c, String sha256) {
            return new LoadedTrajectory(source, TrajectoryFormat.TUM, reason,
                    SpatialTrajectory.ofFirst(n, c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]), sha256, false);
        }
    }
}
