package org.trajeval.core.io.bag;

import java.util.HashMap;
import java.util.Map;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * Where a message type keeps its stamp, pose and frame names, as evo reads them:
 * <ul>
 * <li>geometry_msgs PoseStamped: {@code pose}; PoseWithCovarianceStamped and nav_msgs Odometry:
 * {@code pose.pose}; TransformStamped: {@code transform};</li>
 * <li>nav_msgs Path: every element of {@code poses} (a PoseStamped); tf2_msgs TFMessage: every
 * element of {@code transforms} (a TransformStamped);</li>
 * <li>any other type: the field named by {@code --pose-field}.</li>
 * </ul>
 * A pose is a message with {@code position} (x, y, z) and {@code orientation} (x, y, z, w), or
 * {@code translation} and {@code rotation}. The stamp is {@code header.stamp}.
 *
 * @param repeatPath the sequence field whose elements are poses, or null
 * @param posePath the pose field (relative to the element when repeated)
 * @param hasStamp whether the (element) type has {@code header.stamp}
 * @param lastMessageOnly whether only the last message counts (nav_msgs Path: the latest plan)
 */
record PoseLayout(String repeatPath, String posePath, boolean hasStamp, boolean lastMessageOnly,
        Map<String, Integer> captures) {

    /**
     * @param poseField the user's field path, or null for the type's own
     * @throws InputException (UNKNOWN_TOPIC) when the type holds no pose trajeval can find
     */
    static PoseLayout of(String source, String topic, MessageType type, String poseField) {
        String name = type.name();
        String repeat = null;
        String pose;
        boolean last = false;
        switch (name) {
            case "geometry_msgs/PoseStamped" -> pose = "pose";
            case "geometry_msgs/PoseWithCovarianceStamped", "nav_msgs/Odometry" -> pose = "pose.pose";
            case "geometry_msgs/TransformStamped" -> pose = "transform";
            case "nav_msgs/Path" -> {
                repeat = "poses";
                pose = "pose";
                last = true;
            }
            case "tf2_msgs/TFMessage", "tf/tfMessage" -> {
                repeat = "transforms";
                pose = "transform";
            }
            default -> pose = null;
        }
        if (poseField != null) {
            pose = poseField;
        }
        if (pose == null) {
            throw new InputException(source, 0, topic, InputProblem.UNKNOWN_TOPIC, "topic " + topic + " has type "
                    + name + ", which holds no pose trajeval knows (it reads geometry_msgs PoseStamped, "
                    + "PoseWithCovarianceStamped, TransformStamped, nav_msgs Odometry and Path, tf2_msgs TFMessage); "
                    + "name the pose with --pose-field FIELD.PATH", name);
        }
        MessageType element = type;
        if (repeat != null) {
            MessageType.Field seq = type.field(repeat);
            if (seq == null || seq.nested() == null || seq.arity() != MessageType.Arity.SEQUENCE) {
                throw new InputException(source, 0, topic, InputProblem.UNKNOWN_TOPIC, "type " + name + " on topic "
                        + topic + " has no message sequence '" + repeat + "' in its stored definition", repeat);
            }
            element = seq.nested();
        }
        Map<String, Integer> captures = new HashMap<>();
        MessageType poseType = walk(source, topic, element, pose);
        String[] parts = poseParts(poseType);
        if (parts == null) {
            throw new InputException(source, 0, topic, InputProblem.UNKNOWN_TOPIC, "field " + pose + " of type "
                    + name + " on topic " + topic + " is a " + poseType.name() + ", not a pose (position and "
                    + "orientation, or translation and rotation)", pose);
        }
        String p = pose + "." + parts[0] + ".";
        String q = pose + "." + parts[1] + ".";
        captures.put(p + "x", PosePlan.X);
        captures.put(p + "y", PosePlan.Y);
        captures.put(p + "z", PosePlan.Z);
        captures.put(q + "x", PosePlan.QX);
        captures.put(q + "y", PosePlan.QY);
        captures.put(q + "z", PosePlan.QZ);
        captures.put(q + "w", PosePlan.QW);
        boolean stamp = false;
        MessageType.Field header = element.field("header");
        if (header != null && header.nested() != null) {
            MessageType.Field st = header.nested().field("stamp");
            if (st != null && st.primitive() == Primitive.TIME) {
                captures.put("header.stamp", PosePlan.SEC);
                stamp = true;
            } else if (st != null && st.nested() != null && st.nested().fields().size() == 2) {
                captures.put("header.stamp." + st.nested().fields().get(0).name(), PosePlan.SEC);
                captures.put("header.stamp." + st.nested().fields().get(1).name(), PosePlan.NSEC);
                stamp = true;
            }
            MessageType.Field frame = header.nested().field("frame_id");
            if (frame != null && frame.primitive() == Primitive.STRING) {
                captures.put("header.frame_id", -1 - PosePlan.FRAME);
            }
        }
        MessageType.Field child = element.field("child_frame_id");
        if (child != null && child.primitive() == Primitive.STRING) {
            captures.put("child_frame_id", -1 - PosePlan.CHILD);
        }
        return new PoseLayout(repeat, pose, stamp, last, Map.copyOf(captures));
    }

    private static MessageType walk(String source, String topic, MessageType type, String path) {
        MessageType t = type;
        for (String part : path.split("\\.", -1)) {
            MessageType.Field f = t.field(part);
            if (f == null || f.nested() == null || f.arity() != MessageType.Arity.ONE) {
                throw new InputException(source, 0, topic, InputProblem.UNKNOWN_TOPIC, "type " + type.name()
                        + " on topic " + topic + " has no message field '" + path + "' (at '" + part + "'; fields of "
                        + t.name() + ": " + names(t) + ")", path);
            }
            t = f.nested();
        }
        return t;
    }

    private static String names(MessageType t) {
        StringBuilder sb = new StringBuilder();
        for (MessageType.Field f : t.fields()) {
            sb.append(sb.length() == 0 ? "" : ", ").append(f.name());
        }
        return sb.toString();
    }

    /** @return {position, orientation} or {translation, rotation} when the type is a pose, else null */
    private static String[] poseParts(MessageType t) {
        for (String[] pair : new String[][] {{"position", "orientation"}, {"translation", "rotation"}}) {
            MessageType.Field a = t.field(pair[0]);
            MessageType.Field b = t.field(pair[1]);
            if (a != null && b != null && a.nested() != null && b.nested() != null
                    && has(a.nested(), "x", "y", "z") && has(b.nested(), "x", "y", "z", "w")) {
                return pair;
            }
        }
        return null;
    }

    private static boolean has(MessageType t, String... names) {
        for (String n : names) {
            MessageType.Field f = t.field(n);
            if (f == null || f.primitive() == null || f.arity() != MessageType.Arity.ONE) {
                return false;
            }
        }
        return true;
    }
}
