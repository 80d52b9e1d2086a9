package org.trajeval.core.io.bag;

import java.nio.file.Path;
import java.util.Objects;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TimestampOrder;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * Reads one trajectory out of a bag: a topic of a pose-bearing type, or a TF trajectory
 * {@code /tf:PARENT.CHILD} (see {@link TfTrajectory}). Poses keep the bag's order; the timestamp
 * order and duplicate policies and the quaternion tolerance of {@link ReadOptions} apply as for files.
 */
public final class BagTrajectoryReader {
    private BagTrajectoryReader() {
    }

    /**
     * @param path a bag file or rosbag2 folder
     * @param bag topic, stamp source, pose field, limits
     * @param read order and duplicate policies, quaternion tolerance
     * @throws InputException on any bad input (exit 2): broken container, unknown topic, no pose
     */
    public static LoadedTrajectory read(Path path, BagReadOptions bag, ReadOptions read) {
        Objects.requireNonNull(path, "path");
        Objects.requireNonNull(bag, "bag");
        Objects.requireNonNull(read, "read");
        Objects.requireNonNull(bag.topic(), "topic");
        String source = path.toString();
        PoseColumns cols = new PoseColumns();
        String reason;
        try (BagContainer c = Bags.open(path, source, bag.limits(), bag.integrity())) {
            if (TfTrajectory.isTfId(bag.topic())) {
                long dropped = TfTrajectory.read(c, source, bag, cols);
                reason = "auto: " + c.kind() + " bag, TF " + bag.topic() + (dropped == 0 ? ""
                        : ", " + dropped + " stamps dropped (another edge of the path has no stamps around them)");
            } else {
                TopicPoses.read(c, source, bag, cols);
                reason = "auto: " + c.kind() + " bag, topic " + bag.topic();
            }
        }
        String what = source + ":" + bag.topic();
        if (cols.n == 0) {
            throw new InputException(what, 0, bag.topic(), InputProblem.EMPTY, "topic " + bag.topic()
                    + " holds no pose", null);
        }
        int[] order = order(what, cols, read);
        checkQuaternions(what, cols, read.quaternionTolerance());
        SpatialTrajectory t;
        if (order == null) { // the columns as read, spare capacity and all: no copy
            t = SpatialTrajectory.ofFirst(cols.n, cols.t, cols.x, cols.y, cols.z, cols.qw, cols.qx, cols.qy, cols.qz);
        } else {
            double[][] d = cols.columns(order);
            t = SpatialTrajectory.of(d[0], d[1], d[2], d[3], d[4], d[5], d[6], d[7]);
        }
        return new LoadedTrajectory(what, TrajectoryFormat.BAG, reason, t, null, false);
    }

    /** @return the sorting permutation, or null when the poses stay in bag order */
    private static int[] order(String what, PoseColumns c, ReadOptions read) {
        boolean keep = read.duplicates() == DuplicateTimestamps.KEEP;
        int[] order = null;
        double[] t = c.t;
        if (read.order() == TimestampOrder.SORT) {
            boolean sorted = true;
            for (int i = 1; i < c.n && sorted; i++) {
                sorted = t[i] >= t[i - 1];
            }
            if (!sorted) {
                Integer[] idx = new Integer[c.n];
                for (int i = 0; i < c.n; i++) {
                    idx[i] = i;
                }
                java.util.Arrays.sort(idx, (a, b) -> Double.compare(t[a], t[b]));
                order = new int[c.n];
                for (int i = 0; i < c.n; i++) {
                    order[i] = idx[i];
                }
            }
        }
        for (int k = 1; k < c.n; k++) {
            int i = order == null ? k : order[k];
            int j = order == null ? k - 1 : order[k - 1];
            if (t[i] < t[j]) {
                throw new InputException(what, 0, "header.stamp", InputProblem.DECREASING_TIMESTAMP, "pose " + (k + 1)
                        + " has stamp " + t[i] + " s, before pose " + k + " (" + t[j]
                        + " s): stamps must increase. Pass --sort, or --stamps log", null);
            }
            if (t[i] == t[j] && !keep) {
                throw new InputException(what, 0, "header.stamp", InputProblem.DUPLICATE_TIMESTAMP, "poses " + k
                        + " and " + (k + 1) + " have the same stamp " + t[i] + " s: stamps must be unique (--duplicates "
                        + "keep keeps both, as evo does)", null);
            }
        }
        return order;
    }

    private static void checkQuaternions(String what, PoseColumns c, double tol) {
        for (int i = 0; i < c.n; i++) {
            double norm = Math.sqrt(c.qw[i] * c.qw[i] + c.qx[i] * c.qx[i] + c.qy[i] * c.qy[i] + c.qz[i] * c.qz[i]);
            double[] all = {c.t[i], c.x[i], c.y[i], c.z[i], norm};
            for (double v : all) {
                if (!Double.isFinite(v)) {
                    throw new InputException(what, 0, "pose", InputProblem.NOT_FINITE, "pose " + (i + 1)
                            + " must have finite stamp, position (m) and orientation", String.valueOf(v));
                }
            }
            if (!(Math.abs(norm - 1.0) <= tol)) {
                throw new InputException(what, 0, "orientation", InputProblem.NON_UNIT_QUATERNION, "pose " + (i + 1)
                        + " must have a unit quaternion (| |q| - 1 | <= " + tol + ")", "|q| = " + norm);
            }
        }
    }
}
