package org.trajeval.core.io.bag;

import com.code_intelligence.jazzer.api.FuzzedDataProvider;
import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.trajeval.core.InputException;
import org.trajeval.core.io.ReadOptions;

/**
 * Coverage-guided fuzzing of the bag containers (MCAP, ROS 1, rosbag2 sqlite3) and of the CDR
 * decoder with the message-definition parser. The contract: whatever the bytes, reading returns
 * or throws {@link InputException}; any other exception or error is a bug. In a normal test run
 * each target replays its committed corpus from
 * {@code src/test/resources/org/trajeval/core/io/bag/BagFuzzTestInputs/<method>/} (seeds written
 * by {@link BagFuzzSeeds}, plus whatever fuzzing found); {@code gradle :core:fuzz
 * -Dfuzz.target=org.trajeval.core.io.bag.BagFuzzTest#mcap} fuzzes one target.
 *
 * <p>Limits are tight (1 MiB records, 10 000 messages) so a fuzzed length cannot make the fuzzer
 * itself run out of memory; the refusal paths are the same as with the defaults.
 */
class BagFuzzTest {
    private static final Path SCRATCH = scratch();
    private static final BagLimits LIMITS = new BagLimits(1 << 20, 10_000);
    private static final String[] TOPICS = {"/pose", "/odom", "/tf:map.base_link", "/tf:odom.base_link"};

    @FuzzTest(maxDuration = "10m")
    void mcap(FuzzedDataProvider data) throws IOException {
        readAll(data.consumeRemainingAsBytes(), "input.mcap");
    }

    @FuzzTest(maxDuration = "10m")
    void ros1(FuzzedDataProvider data) throws IOException {
        readAll(data.consumeRemainingAsBytes(), "input.bag");
    }

    @FuzzTest(maxDuration = "10m")
    void sqlite3(FuzzedDataProvider data) throws IOException {
        readAll(data.consumeRemainingAsBytes(), "input.db3");
    }

    /** A definition text (up to the first NUL) parsed and compiled, then the rest decoded as CDR and as ROS 1. */
    @FuzzTest(maxDuration = "10m")
    void cdr(FuzzedDataProvider data) {
        String type = data.pickValue(List.of("geometry_msgs/msg/PoseStamped", "nav_msgs/msg/Odometry",
                "tf2_msgs/msg/TFMessage", "nav_msgs/msg/Path", "my_msgs/msg/State"));
        String definition = data.consumeBoolean() ? "" : data.consumeString(2000);
        byte[] message = data.consumeRemainingAsBytes();
        for (boolean cdr : new boolean[] {true, false}) {
            try {
                BagChannel ch = new BagChannel(1, "/t", type, definition.isEmpty() ? "" : cdr ? "ros2msg" : "ros1msg",
                        definition, cdr ? "cdr" : "ros1");
                PosePlan plan = TopicPoses.plan("fuzz", ch, type.startsWith("my_msgs") ? "pose" : null);
                plan.decode(message, 0, message.length, (v, s) -> {
                });
            } catch (InputException | PosePlan.DecodeException expected) {
                // the documented refusals
            }
        }
    }

    private static void readAll(byte[] bytes, String name) throws IOException {
        Path file = SCRATCH.resolve(name);
        Files.write(file, bytes);
        try {
            try {
                BagSummary.of(file, LIMITS);
            } catch (InputException expected) {
                // refused
            }
            for (String topic : TOPICS) {
                try {
                    BagTrajectoryReader.read(file, new BagReadOptions(topic, StampSource.HEADER, null, LIMITS),
                            ReadOptions.defaults());
                } catch (InputException expected) {
                    // refused
                }
            }
        } finally {
            Files.deleteIfExists(file);
        }
    }

    private static Path scratch() {
        try {
            Path shm = Path.of("/dev/shm");
            Path dir = Files.isDirectory(shm) && Files.isWritable(shm)
                    ? Files.createTempDirectory(shm, "trajeval-bagfuzz") : Files.createTempDirectory("trajeval-bagfuzz");
            dir.toFile().deleteOnExit();
            return dir;
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
    }
}
