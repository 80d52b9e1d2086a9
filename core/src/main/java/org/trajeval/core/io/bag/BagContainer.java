package org.trajeval.core.io.bag;

import java.util.List;
import java.util.function.Predicate;

/**
 * The container layer of a bag (MCAP, ROS 1 bag, rosbag2 sqlite3): hands out channels and, streaming,
 * the messages of the wanted ones; never more than one chunk in memory.
 */
public interface BagContainer extends AutoCloseable {
    /** @return the container's name, e.g. "MCAP" */
    String kind();

    /** @return every channel of the bag, in id order */
    List<BagChannel> channels();

    /**
     * Hands every message of the wanted channels to the sink, reading only the parts of the file
     * that can hold them when the file has an index.
     */
    void read(Predicate<BagChannel> wanted, MessageSink sink);

    @Override
    void close();
}
