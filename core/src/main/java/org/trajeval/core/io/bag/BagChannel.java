package org.trajeval.core.io.bag;

import java.util.Objects;

/**
 * One topic of a bag as its container describes it.
 *
 * @param id the container's id of the channel (MCAP channel id, ROS 1 connection id, rosbag2 topic id)
 * @param topic topic name, e.g. {@code /odom}
 * @param type message type name as stored, e.g. {@code nav_msgs/msg/Odometry} or {@code nav_msgs/Odometry}
 * @param schemaEncoding {@code ros2msg}, {@code ros1msg}, or empty when the file stores no schema text
 * @param schema the message definition text stored in the file (empty when none)
 * @param messageEncoding {@code cdr} (ROS 2) or {@code ros1}
 */
public record BagChannel(int id, String topic, String type, String schemaEncoding, String schema,
        String messageEncoding) {
    /** @throws NullPointerException on a missing component */
    public BagChannel {
        Objects.requireNonNull(topic, "topic");
        Objects.requireNonNull(type, "type");
        Objects.requireNonNull(schemaEncoding, "schemaEncoding");
        Objects.requireNonNull(schema, "schema");
        Objects.requireNonNull(messageEncoding, "messageEncoding");
    }
}
