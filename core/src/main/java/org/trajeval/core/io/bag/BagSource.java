package org.trajeval.core.io.bag;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;

/**
 * A bag and the topic to read from it, as named on a command line or in a manifest: either a
 * path plus a topic given apart ({@code --ref-topic /odom}), or {@code BAG:TOPIC} in one argument
 * ({@code run.mcap:/odom}, {@code run.bag:/tf:map.base_link}), split at the first colon whose
 * left part is an existing file or folder.
 *
 * @param path the bag file or rosbag2 folder
 * @param topic the topic or TF trajectory id
 */
public record BagSource(Path path, String topic) {
    /** @throws NullPointerException on a missing part */
    public BagSource {
        java.util.Objects.requireNonNull(path, "path");
        java.util.Objects.requireNonNull(topic, "topic");
    }

    /**
     * @param argument the path as given, maybe with {@code :TOPIC}
     * @param topicOption the topic given apart, or null
     * @return the bag source, or null when the argument names no bag and no topic was given apart
     * @throws InputException when a topic is given both ways, or given for a file that is not a bag
     */
    public static BagSource resolve(String argument, String topicOption) {
        Path whole = Paths.get(argument);
        if (Files.exists(whole)) {
            if (topicOption == null) {
                return null;
            }
            if (Bags.kind(whole) == null) {
                throw new InputException(argument, 0, null, InputProblem.INVALID_OPTION, "a topic (" + topicOption
                        + ") applies to bags only, and this is not a bag (MCAP, ROS 1 bag, rosbag2 sqlite3 or folder)",
                        null);
            }
            return new BagSource(whole, topicOption);
        }
        for (int i = argument.indexOf(':'); i > 0; i = argument.indexOf(':', i + 1)) {
            Path p = Paths.get(argument.substring(0, i));
            if (Files.exists(p) && Bags.kind(p) != null) {
                if (topicOption != null) {
                    throw new InputException(argument, 0, null, InputProblem.INVALID_OPTION, "the topic is given twice ("
                            + argument.substring(i + 1) + " in the argument and " + topicOption + " as an option); "
                            + "give it once", null);
                }
                return new BagSource(p, argument.substring(i + 1));
            }
        }
        return null;
    }
}
