package org.trajeval.core.io.bag;

import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * A TF trajectory in evo's syntax, {@code /tf:PARENT.CHILD} (the TF topic, then the two frames
 * split at the first dot): the transform PARENT -> CHILD composed along the TF tree of the topic
 * and {@code /tf_static}, at each stamp of the driving edge, the dynamic edge nearest the child on
 * the path. Times at which another dynamic edge of the path has no stamps on both sides are
 * dropped (tf2 would refuse to extrapolate) and counted.
 */
final class TfTrajectory {
    /** Topic of the transforms valid at all times. */
    static final String STATIC_TOPIC = "/tf_static";

    /**
     * @param topic the TF topic
     * @param parent the parent frame
     * @param child the child frame
     */
    record TfId(String topic, String parent, String child) {
    }

    private TfTrajectory() {
    }

    static boolean isTfId(String id) {
        return parse(id) != null;
    }

    /** @return the parts of {@code /tf:PARENT.CHILD}, or null when the text is not such an id */
    static TfId parse(String id) {
        int colon = id.indexOf(':');
        if (colon <= 0) {
            return null;
        }
        String frames = id.substring(colon + 1);
        int dot = frames.indexOf('.');
        if (dot <= 0 || dot == frames.length() - 1) {
            return null;
        }
        return new TfId(id.substring(0, colon), TfTree.frame(frames.substring(0, dot)),
                TfTree.frame(frames.substring(dot + 1)));
    }

    /** Reads the whole TF tree of a bag. */
    static TfTree tree(BagContainer bag, String source, String topic, BagLimits limits) {
        TfTree tree = new TfTree(source);
        TopicPoses.channels(bag, source, topic);
        Map<Integer, PosePlan> plans = new HashMap<>();
        for (BagChannel c : bag.channels()) {
            if (c.topic().equals(topic) || c.topic().equals(STATIC_TOPIC)) {
                plans.put(c.id(), TopicPoses.plan(source, c, null));
            }
        }
        long[] count = {0};
        bag.read(c -> plans.containsKey(c.id()), (ch, logTimeNs, data, off, len) -> {
            boolean isStatic = ch.topic().equals(STATIC_TOPIC);
            try {
                plans.get(ch.id()).decode(data, off, len, (v, s) -> {
                    if (++count[0] > limits.maxMessages()) {
                        throw new InputException(source, 0, topic, InputProblem.TOO_LARGE, "the TF topics hold more "
                                + "than " + limits.maxMessages() + " transforms (the limit)", null);
                    }
                    tree.add(s[PosePlan.FRAME], s[PosePlan.CHILD], isStatic, v);
                });
            } catch (PosePlan.DecodeException e) {
                throw new InputException(source, 0, ch.topic(), InputProblem.CORRUPT_BAG, "a message of topic "
                        + ch.topic() + " (" + ch.type() + ") does not decode: " + e.getMessage(), null);
            }
        });
        tree.finish();
        return tree;
    }

    /**
     * Reads {@code /tf:PARENT.CHILD} into the columns.
     *
     * @return the number of driving stamps dropped because another edge could not be interpolated there
     */
    static long read(BagContainer bag, String source, BagReadOptions options, PoseColumns out) {
        TfId id = parse(options.topic());
        TfTree tree = tree(bag, source, id.topic(), options.limits());
        List<List<TfTree.Edge>> path = tree.path(id.parent(), id.child(), options.topic());
        List<TfTree.Edge> climb = path.get(0);
        List<TfTree.Edge> descend = path.get(1);
        TfTree.Edge driving = null;
        for (int i = descend.size() - 1; i >= 0 && driving == null; i--) {
            driving = descend.get(i).isStatic ? null : descend.get(i);
        }
        for (int i = 0; i < climb.size() && driving == null; i++) {
            driving = climb.get(i).isStatic ? null : climb.get(i);
        }
        if (driving == null) {
            throw new InputException(source, 0, options.topic(), InputProblem.UNKNOWN_TOPIC, "the TF path from '"
                    + id.parent() + "' to '" + id.child() + "' holds only static transforms: no trajectory", null);
        }
        long dropped = 0;
        double[] acc = new double[7];
        double[] e = new double[7];
        PoseColumns d = driving.series;
        for (int i = 0; i < d.n; i++) {
            double t = d.t[i];
            if (!pose(climb, descend, t, acc, e)) {
                dropped++;
                continue;
            }
            if (out.n >= options.limits().maxMessages()) {
                throw new InputException(source, 0, options.topic(), InputProblem.TOO_LARGE, "TF trajectory "
                        + options.topic() + " holds more than " + options.limits().maxMessages() + " poses", null);
            }
            out.add(t, acc[0], acc[1], acc[2], acc[3], acc[4], acc[5], acc[6]);
        }
        return dropped;
    }

    /** acc = (climb edges composed)^-1 * (descend edges composed) at t; false when an edge cannot be had at t. */
    private static boolean pose(List<TfTree.Edge> climb, List<TfTree.Edge> descend, double t, double[] acc,
            double[] e) {
        boolean first = true;
        if (!climb.isEmpty()) {
            // climb lists parent -> ... -> common: T_common_parent = edges composed from the common end down
            for (int k = climb.size() - 1; k >= 0; k--) {
                if (!TfTree.at(climb.get(k), t, e)) {
                    return false;
                }
                if (first) {
                    System.arraycopy(e, 0, acc, 0, 7);
                    first = false;
                } else {
                    TfTree.compose(acc, e);
                }
            }
            TfTree.invert(acc);
        }
        for (TfTree.Edge edge : descend) {
            if (!TfTree.at(edge, t, e)) {
                return false;
            }
            if (first) {
                System.arraycopy(e, 0, acc, 0, 7);
                first = false;
            } else {
                TfTree.compose(acc, e);
            }
        }
        return true;
    }
}
