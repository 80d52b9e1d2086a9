package org.trajeval.core.io.bag;

/**
 * Limits the bag readers check every length field against before allocating.
 *
 * @param maxRecordBytes largest record, chunk (compressed or not) or summary section read into memory (bytes)
 * @param maxMessages largest number of messages taken from one topic
 */
public record BagLimits(long maxRecordBytes, long maxMessages) {
    /** Default: records up to 1 GiB, 200 million messages. */
    public static final BagLimits DEFAULT = new BagLimits(1L << 30, 200_000_000L);

    /** @throws IllegalArgumentException on a limit that is not positive or does not fit an array */
    public BagLimits {
        if (maxRecordBytes <= 0 || maxRecordBytes > Integer.MAX_VALUE - 16) {
            throw new IllegalArgumentException("maxRecordBytes must be in 1.." + (Integer.MAX_VALUE - 16)
                    + ", found " + maxRecordBytes);
        }
        if (maxMessages <= 0) {
            throw new IllegalArgumentException("maxMessages must be positive, found " + maxMessages);
        }
    }
}
