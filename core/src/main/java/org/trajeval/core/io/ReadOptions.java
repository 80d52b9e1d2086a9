package org.trajeval.core.io;

import java.nio.file.Path;
import org.trajeval.core.io.bag.BagReadOptions;

/**
 * How to read a trajectory file.
 *
 * @param format the format, or {@code null} to detect it from extension and content
 * @param csv layout of CSV files
 * @param order what to do with unsorted timestamps
 * @param kittiTimes times file for KITTI poses (one time in s per line), or {@code null}
 * @param quaternionTolerance largest accepted | |q| - 1 |
 * @param maxBytes largest accepted file size (bytes)
 * @param maxPoses largest accepted number of poses
 * @param duplicates what to do with two poses that have the same timestamp
 * @param bag what to read from a bag (topic, stamps, pose field); its topic is null when the path
 *     names it ({@code BAG:TOPIC}) or the file is not a bag
 */
public record ReadOptions(TrajectoryFormat format, CsvLayout csv, TimestampOrder order, Path kittiTimes,
        double quaternionTolerance, long maxBytes, long maxPoses, DuplicateTimestamps duplicates,
        BagReadOptions bag) {

    /** Default largest file: 4 GiB. */
    public static final long DEFAULT_MAX_BYTES = 4L << 30;
    /** Default largest pose count: 200 million. */
    public static final long DEFAULT_MAX_POSES = 200_000_000L;

    /** @return auto-detected format, default CSV layout, refuse unsorted, tolerance 1e-3, refuse duplicates */
    public static ReadOptions defaults() {
        return new ReadOptions(null, CsvLayout.DEFAULT, TimestampOrder.REFUSE_UNSORTED, null, 1e-3,
                DEFAULT_MAX_BYTES, DEFAULT_MAX_POSES, DuplicateTimestamps.REFUSE, BagReadOptions.DEFAULT);
    }

    /** @return a copy with a fixed format ({@code null}: auto) */
    public ReadOptions withFormat(TrajectoryFormat f) {
        return new ReadOptions(f, csv, order, kittiTimes, quaternionTolerance, maxBytes, maxPoses, duplicates, bag);
    }

    /** @return a copy with another CSV layout */
    public ReadOptions withCsv(CsvLayout c) {
        return new ReadOptions(format, c, order, kittiTimes, quaternionTolerance, maxBytes, maxPoses, duplicates, bag);
    }

    /** @return a copy with another timestamp-order policy */
    public ReadOptions withOrder(TimestampOrder o) {
        return new ReadOptions(format, csv, o, kittiTimes, quaternionTolerance, maxBytes, maxPoses, duplicates, bag);
    }

    /** @return a copy with a KITTI times file */
    public ReadOptions withKittiTimes(Path p) {
        return new ReadOptions(format, csv, order, p, quaternionTolerance, maxBytes, maxPoses, duplicates, bag);
    }

    /** @return a copy with another duplicate-timestamp policy ({@link DuplicateTimestamps#KEEP} as evo) */
    public ReadOptions withDuplicates(DuplicateTimestamps d) {
        return new ReadOptions(format, csv, order, kittiTimes, quaternionTolerance, maxBytes, maxPoses, d, bag);
    }

    /** @return a copy with other bag options (topic, stamps, pose field) */
    public ReadOptions withBag(BagReadOptions b) {
        return new ReadOptions(format, csv, order, kittiTimes, quaternionTolerance, maxBytes, maxPoses, duplicates, b);
    }

    /** @return a copy with other size limits */
    public ReadOptions withLimits(long bytes, long poses) {
        return new ReadOptions(format, csv, order, kittiTimes, quaternionTolerance, bytes, poses, duplicates, bag);
    }
}
