package org.trajeval.core.io.bag;

/** Receives the messages a container hands out, in the container's order (chunk by chunk). */
@FunctionalInterface
public interface MessageSink {
    /**
     * @param channel the message's channel
     * @param logTimeNs the recording's log time (ns since the epoch)
     * @param data the array holding the serialised message; valid only during the call
     * @param offset first byte of the message in {@code data}
     * @param length length of the message (bytes)
     */
    void message(BagChannel channel, long logTimeNs, byte[] data, int offset, int length);
}
