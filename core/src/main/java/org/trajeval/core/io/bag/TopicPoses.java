package org.trajeval.core.io.bag;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Reads the poses of one topic of an open bag: each channel's definition is parsed once into a
 * {@link PosePlan}, then every message is decoded straight into the columns.
 */
final class TopicPoses {
    private TopicPoses() {
    }

    /** @return the channels of that topic, or a refusal that lists the topics there are */
    static List<BagChannel> channels(BagContainer bag, String source, String topic) {
        List<BagChannel> out = new ArrayList<>();
        for (BagChannel c : bag.channels()) {
            if (c.topic().equals(topic)) {
                out.add(c);
            }
        }
        if (out.isEmpty()) {
            throw new InputException(source, 0, topic, InputProblem.UNKNOWN_TOPIC, "the bag has no topic " + topic
                    + "; its topics are: " + topicList(bag), topic);
        }
        return out;
    }

    static String topicList(BagContainer bag) {
        TreeMap<String, String> topics = new TreeMap<>();
        for (BagChannel c : bag.channels()) {
            topics.putIfAbsent(c.topic(), c.type());
        }
        StringBuilder sb = new StringBuilder();
        for (Map.Entry<String, String> e : topics.entrySet()) {
            sb.append(sb.length() == 0 ? "" : ", ").append(e.getKey()).append(" (").append(e.getValue()).append(')');
        }
        return sb.length() == 0 ? "(none)" : sb.toString();
    }

    /** @return the compiled plan of a channel */
    static PosePlan plan(String source, BagChannel c, String poseField) {
        return plan(source, c, poseField, null);
    }

    /**
     * @param layoutOut when not null, receives the layout (index 0)
     */
    static PosePlan plan(String source, BagChannel c, String poseField, PoseLayout[] layoutOut) {
        boolean cdr = c.messageEncoding().equalsIgnoreCase("cdr");
        boolean ros1 = c.messageEncoding().equalsIgnoreCase("ros1");
        if (!cdr && !ros1) {
            throw BagProblems.unsupported(source, "topic " + c.topic() + " is encoded as '" + c.messageEncoding()
                    + "'; trajeval decodes cdr (ROS 2) and ros1", c.messageEncoding());
        }
        String enc = c.schemaEncoding();
        if (!enc.isEmpty() && !enc.equals("ros2msg") && !enc.equals("ros1msg")) {
            throw BagProblems.unsupported(source, "the definition of topic " + c.topic() + " is in '" + enc
                    + "'; trajeval parses ros2msg and ros1msg", enc);
        }
        MessageType type = MessageDefinitions.parse(source, c.topic(), c.type(), c.schema(),
                cdr ? MessageDefinitions.Dialect.ROS2 : MessageDefinitions.Dialect.ROS1);
        PoseLayout layout = PoseLayout.of(source, c.topic(), type, poseField);
        if (layoutOut != null) {
            layoutOut[0] = layout;
        }
        return PosePlan.compile(type, layout.captures(), layout.repeatPath(), cdr);
    }

    /** @return the plan of a channel read as a topic: the frame names are skipped, not read (no string per message) */
    private static PosePlan posesOnly(String source, BagChannel c, String poseField, PoseLayout[] layoutOut) {
        plan(source, c, poseField, layoutOut); // checks encodings and the definition, gives the layout
        PoseLayout layout = layoutOut[0];
        Map<String, Integer> numbers = new HashMap<>();
        layout.captures().forEach((path, slot) -> {
            if (slot >= 0) {
                numbers.put(path, slot);
            }
        });
        boolean cdr = c.messageEncoding().equalsIgnoreCase("cdr");
        MessageType type = MessageDefinitions.parse(source, c.topic(), c.type(), c.schema(),
                cdr ? MessageDefinitions.Dialect.ROS2 : MessageDefinitions.Dialect.ROS1);
        return PosePlan.compile(type, numbers, layout.repeatPath(), cdr);
    }

    /**
     * Reads every pose of the topic into the columns, in the bag's order.
     *
     * @return the number of messages read
     */
    static long read(BagContainer bag, String source, BagReadOptions options, PoseColumns out) {
        List<BagChannel> chans = channels(bag, source, options.topic());
        Map<Integer, PosePlan> plans = new HashMap<>();
        Map<Integer, PoseLayout> layouts = new HashMap<>();
        for (BagChannel c : chans) {
            PoseLayout[] l = new PoseLayout[1];
            plans.put(c.id(), posesOnly(source, c, options.poseField(), l));
            layouts.put(c.id(), l[0]);
            if ("transforms".equals(l[0].repeatPath()) && options.poseField() == null) {
                throw new InputException(source, 0, options.topic(), InputProblem.UNKNOWN_TOPIC, "topic "
                        + options.topic() + " holds the transforms of many TF frames; read one as "
                        + options.topic() + ":PARENT.CHILD (trajeval topics lists the TF tree)", options.topic());
            }
            if (options.stamps() == StampSource.HEADER && !l[0].hasStamp()) {
                throw new InputException(source, 0, options.topic(), InputProblem.UNKNOWN_TOPIC, "type " + c.type()
                        + " of topic " + options.topic() + " has no header.stamp; read its log times with --stamps log",
                        c.type());
            }
        }
        long[] count = {0};
        BagChannel[] current = {null};
        PosePlan[] currentPlan = {null};
        boolean[] currentLastOnly = {false};
        double[] logT = {0};
        boolean useLog = options.stamps() == StampSource.LOG_TIME;
        long max = options.limits().maxMessages();
        PosePlan.Emit emit = (v, s) -> {
            if (out.n >= max) {
                throw new InputException(source, 0, options.topic(), InputProblem.TOO_LARGE, "topic "
                        + options.topic() + " holds more than " + max + " poses (the limit)", null);
            }
            double t = useLog ? logT[0] : v[PosePlan.SEC] + v[PosePlan.NSEC] * 1e-9;
            out.add(t, v[PosePlan.X], v[PosePlan.Y], v[PosePlan.Z], v[PosePlan.QW], v[PosePlan.QX], v[PosePlan.QY],
                    v[PosePlan.QZ]);
        };
        bag.read(c -> c.topic().equals(options.topic()), (ch, logTimeNs, data, off, len) -> {
            if (ch != current[0]) { // a new channel: look its plan up once, not per message
                current[0] = ch;
                currentPlan[0] = plans.get(ch.id());
                currentLastOnly[0] = currentPlan[0] != null && layouts.get(ch.id()).lastMessageOnly();
            }
            PosePlan p = currentPlan[0];
            if (p == null) {
                return;
            }
            if (currentLastOnly[0]) {
                out.clear();
            }
            logT[0] = logTimeNs / 1e9;
            try {
                p.decode(data, off, len, emit);
            } catch (PosePlan.DecodeException e) {
                throw new InputException(source, 0, options.topic(), InputProblem.CORRUPT_BAG, "message "
                        + (count[0] + 1) + " of topic " + options.topic() + " (" + ch.type() + ") does not decode: "
                        + e.getMessage(), null);
            }
            count[0]++;
        });
        return count[0];
    }
}
