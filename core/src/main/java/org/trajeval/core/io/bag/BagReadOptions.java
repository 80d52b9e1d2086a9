package org.trajeval.core.io.bag;

import java.util.Objects;

/**
 * What to read from a bag.
 *
 * @param topic a topic name ({@code /odom}) or a TF trajectory in evo's syntax ({@code /tf:map.base_link});
 *     null when the path names it ({@code BAG:TOPIC})
 * @param stamps header stamps (default, as evo) or log times
 * @param poseField the field holding the pose for a type trajeval does not know ({@code a.b.pose}), or null
 * @param limits record and message limits
 * @param integrity the MCAP checksums to verify (all, or those of the chunks read)
 */
public record BagReadOptions(String topic, StampSource stamps, String poseField, BagLimits limits,
        BagIntegrity integrity) {
    /** No topic, header stamps, the type's own pose field, default limits, every checksum. */
    public static final BagReadOptions DEFAULT = new BagReadOptions(null, StampSource.HEADER, null, BagLimits.DEFAULT);

    /** @throws NullPointerException on a missing stamp source, limits or integrity */
    public BagReadOptions {
        Objects.requireNonNull(stamps, "stamps");
        Objects.requireNonNull(limits, "limits");
        Objects.requireNonNull(integrity, "integrity");
    }

    /** The checksums of the summary and of every chunk read ({@link BagIntegrity#CHUNKS}, the default). */
    public BagReadOptions(String topic, StampSource stamps, String poseField, BagLimits limits) {
        this(topic, stamps, poseField, limits, BagIntegrity.CHUNKS);
    }

    /** @return header stamps, the type's own pose field, default limits */
    public static BagReadOptions of(String topic) {
        return new BagReadOptions(topic, StampSource.HEADER, null, BagLimits.DEFAULT);
    }

    /** @return a copy reading another topic */
    public BagReadOptions withTopic(String t) {
        return new BagReadOptions(t, stamps, poseField, limits, integrity);
    }
}
