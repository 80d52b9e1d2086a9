package org.trajeval.core.io.bag;

/**
 * Which checksums an MCAP bag must pass before it is read (ROS 1 bags carry none; rosbag2 sqlite3
 * files are checked by SQLite). A CRC of 0 means "not computed" (mcap.dev/spec) and is never
 * compared.
 */
public enum BagIntegrity {
    /**
     * The data section CRC too ({@link McapDataCrc}: one sequential pass over every byte before the
     * Data End, so a changed byte in a chunk no wanted channel uses is refused as well), besides the
     * summary CRC and the CRC of every chunk read. The default.
     */
    ALL,
    /**
     * The summary CRC and the CRCs of the chunks read only: a bag much larger than its pose topics
     * is read without passing over its other chunks (the images, point clouds) at all.
     */
    CHUNKS
}
