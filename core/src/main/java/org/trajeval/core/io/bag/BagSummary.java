package org.trajeval.core.io.bag;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.trajeval.core.InputException;

/**
 * What a bag holds, for {@code trajeval topics}: each topic with its type, message count and log
 * time span, and the TF tree of {@code /tf} and {@code /tf_static} (one pass over every message).
 *
 * @param kind the container ("MCAP", "ROS 1", ...)
 * @param topics the topics in the order of their first channel
 * @param tf the TF edges (empty when the bag has no /tf)
 */
public record BagSummary(String kind, List<Topic> topics, List<TfEdge> tf) {
    /**
     * @param topic topic name
     * @param type message type
     * @param messages number of messages
     * @param firstLogNs log time of the first message (ns since the epoch), 0 when none
     * @param lastLogNs log time of the last message (ns), 0 when none
     * @param poses whether trajeval can read poses from the type (with no --pose-field); false for TF topics,
     *     which are read as {@code /tf:PARENT.CHILD}
     */
    public record Topic(String topic, String type, long messages, long firstLogNs, long lastLogNs, boolean poses) {
    }

    /**
     * @param parent parent frame
     * @param child child frame
     * @param isStatic from /tf_static
     * @param stamps number of distinct stamps
     * @param firstS first stamp (s)
     * @param lastS last stamp (s)
     */
    public record TfEdge(String parent, String child, boolean isStatic, int stamps, double firstS, double lastS) {
    }

    /** @throws InputException when the bag cannot be read */
    public static BagSummary of(Path path, BagLimits limits) {
        String source = path.toString();
        try (BagContainer bag = Bags.open(path, source, limits)) {
            Map<String, long[]> stats = new LinkedHashMap<>();
            Map<String, String> types = new LinkedHashMap<>();
            for (BagChannel c : bag.channels()) {
                stats.putIfAbsent(c.topic(), new long[] {0, Long.MAX_VALUE, Long.MIN_VALUE});
                types.putIfAbsent(c.topic(), c.type());
            }
            bag.read(c -> true, (c, t, d, o, l) -> {
                long[] s = stats.get(c.topic());
                s[0]++;
                s[1] = Math.min(s[1], t);
                s[2] = Math.max(s[2], t);
            });
            List<Topic> topics = new ArrayList<>();
            for (Map.Entry<String, long[]> e : stats.entrySet()) {
                long[] s = e.getValue();
                topics.add(new Topic(e.getKey(), types.get(e.getKey()), s[0], s[0] == 0 ? 0 : s[1], s[0] == 0 ? 0 : s[2],
                        readable(source, bag, e.getKey())));
            }
            List<TfEdge> tf = new ArrayList<>();
            if (stats.containsKey("/tf") || stats.containsKey(TfTrajectory.STATIC_TOPIC)) {
                String topic = stats.containsKey("/tf") ? "/tf" : TfTrajectory.STATIC_TOPIC;
                TfTree tree = TfTrajectory.tree(bag, source, topic, limits);
                for (TfTree.Edge e : tree.edges().values()) {
                    PoseColumns c = e.series;
                    tf.add(new TfEdge(e.parent, e.child, e.isStatic, c.n, c.n == 0 ? 0 : c.t[0], c.n == 0 ? 0 : c.t[c.n - 1]));
                }
            }
            return new BagSummary(bag.kind(), List.copyOf(topics), List.copyOf(tf));
        }
    }

    private static boolean readable(String source, BagContainer bag, String topic) {
        try {
            for (BagChannel c : bag.channels()) {
                if (c.topic().equals(topic)) {
                    PoseLayout[] l = new PoseLayout[1];
                    TopicPoses.plan(source, c, null, l);
                    if ("transforms".equals(l[0].repeatPath())) {
                        return false;
                    }
                }
            }
            return true;
        } catch (InputException e) {
            return false;
        }
    }
}
