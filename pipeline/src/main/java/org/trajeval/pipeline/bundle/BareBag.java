package org.trajeval.pipeline.bundle;

import java.util.List;

/**
 * A bare bag: one ROS bag file dropped on its own ({@code NAME.mcap}, {@code NAME.bag} or
 * {@code NAME.db3}), scored with the settings of the service configuration's {@code bags.metrics}
 * (which name {@code ref_topic} and {@code est_topic}); its run id is NAME. The container is told
 * from the content when read; the extension only says that the file is a bag.
 */
public final class BareBag {
    /** File name endings of bare bags: MCAP (ROS 2), ROS 1 bag, rosbag2 sqlite3. */
    public static final List<String> EXTENSIONS = List.of(".mcap", ".bag", ".db3");

    private BareBag() {
    }

    /** @return NAME of {@code NAME.mcap} (or .bag, .db3), or {@code null} when the name is no bag's */
    public static String stem(String fileName) {
        for (String ext : EXTENSIONS) {
            if (fileName.endsWith(ext) && fileName.length() > ext.length()) {
                return fileName.substring(0, fileName.length() - ext.length());
            }
        }
        return null;
    }
}
