package org.trajeval.core.io.bag;

/** Which time a pose read from a bag gets. */
public enum StampSource {
    /** The message's {@code header.stamp} (sec + nanosec * 1e-9 s), as evo reads bags: when the pose was valid. */
    HEADER,
    /** The recording's log time (ns / 1e9 s): when the recorder received the message. */
    LOG_TIME
}
