package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code eval}, {@code topics} and {@code convert} on the ROS recordings of ../shared/refdata/ros
 * (missing data fails these tests). Expected numbers are evo's, from evo_bag_reference.json.
 */
class BagCommandsTest {
    /** evo 1.38.1, record mcap_odom_amcl_ape_se3 of evo_bag_reference.json: APE translation RMSE (m). */
    private static final double EVO_APE_RMSE_M = 0.5123009339164919;

    @TempDir
    Path dir;

    static Path ros() {
        Path d = Paths.get(System.getProperty("trajeval.refdata", "../../shared/refdata")).resolve("ros");
        assertTrue(Files.isRegularFile(d.resolve("nav2_turtlebot.mcap")), "missing " + d.toAbsolutePath());
        return d;
    }

    @Test
    void evalOfTwoTopicsOfOneBagGivesEvosApe() throws Exception {
        CliRun r = CliRun.of("eval", ros().resolve("nav2_turtlebot.mcap").toString(),
                "--ref-topic", "/amcl_pose", "--est-topic", "/odom", "--align", "se3", "--json");
        assertEquals(0, r.code(), r.err());
        JsonNode rep = new ObjectMapper().readTree(r.out());
        assertEquals("evo", rep.at("/convention").asText(), "bags default to evo's convention");
        assertEquals(EVO_APE_RMSE_M, rep.at("/ate/trans_m/rmse").asDouble(), 1e-9 * EVO_APE_RMSE_M);
    }

    @Test
    void evalAcceptsBagColonTopicAndTfTrajectories() throws Exception {
        String bag = ros().resolve("nav2_turtlebot.mcap").toString();
        CliRun r = CliRun.of("eval", bag + ":/odom", bag + ":/tf:odom.base_link", "--json");
        assertEquals(0, r.code(), r.err());
        JsonNode rep = new ObjectMapper().readTree(r.out());
        // the TF edge odom->base_link is bit-identical to /odom (README of refdata/ros): APE exactly 0
        assertEquals(2639, rep.at("/association/matched").asInt());
        assertEquals(0.0, rep.at("/ate/trans_m/max").asDouble(), 0.0);
    }

    @Test
    void bagWithoutTopicIsRefusedListingTheTopics() {
        String bag = ros().resolve("nav2_turtlebot.mcap").toString();
        CliRun r = CliRun.of("eval", bag, bag);
        assertEquals(2, r.code());
        assertTrue(r.err().contains("this is a bag: name the topic") && r.err().contains("/amcl_pose"), r.err());
        assertEquals(1, r.err().strip().lines().count(), r.err());
    }

    @Test
    void unknownTopicExitsWith2AndListsTheTopics() {
        CliRun r = CliRun.of("eval", ros().resolve("ROS_example.bag").toString(),
                "--ref-topic", "groundtruth", "--est-topic", "ORB_SLAM");
        assertEquals(2, r.code());
        assertTrue(r.err().contains("no topic ORB_SLAM") && r.err().contains("ORB-SLAM"), r.err());
    }

    @Test
    void topicsListsTypesCountsAndTheTfTree() {
        CliRun r = CliRun.of("topics", ros().resolve("tf_example.bag").toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(r.out().contains("ROS 1 bag"), r.out());
        assertTrue(r.out().matches("(?s).*/tf\\s+tf2_msgs/TFMessage\\s+517\\s.*"), r.out());
        assertTrue(r.out().contains("odom\n    -> base_footprint  (517 stamps"), r.out());
        assertTrue(r.out().contains("-> base_link  (static)"), r.out());
    }

    @Test
    void convertWritesATumFileThatReadsBackAsTheSameTrajectory() throws Exception {
        Path out = dir.resolve("odom.tum");
        String bag = ros().resolve("nav2_turtlebot.mcap").toString();
        CliRun r = CliRun.of("convert", bag, "--topic", "/odom", "--to", "tum", "--out",
                out.toString());
        assertEquals(0, r.code(), r.err());
        List<String> lines = Files.readAllLines(out);
        assertEquals(1 + 2639, lines.size(), "header + one line per /odom message");
        CliRun back = CliRun.of("eval", bag + ":/odom", out.toString(), "--json");
        assertEquals(0, back.code(), back.err());
        assertEquals(0.0, new ObjectMapper().readTree(back.out()).at("/ate/trans_m/max").asDouble(), 0.0);
    }

    @Test
    void convertToKittiWritesTwelveNumbersAPose() throws Exception {
        Path out = dir.resolve("gt.kitti");
        CliRun r = CliRun.of("convert", ros().resolve("ROS_example.bag") + ":groundtruth",
                "--to", "kitti", "--out", out.toString());
        assertEquals(0, r.code(), r.err());
        List<String> lines = Files.readAllLines(out);
        assertEquals(12765, lines.size());
        assertEquals(12, lines.get(0).split(" ").length);
        assertFalse(lines.get(0).startsWith("#"));
    }
}
