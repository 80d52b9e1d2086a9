package org.trajeval.pipeline.dir;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.nio.file.attribute.FileTime;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.pipeline.CoreRunScorer;
import org.trajeval.pipeline.PipelineCommand;
import picocli.CommandLine;

/**
 * Bare bags through the real pipeline ({@code trajeval-pipeline watch --drain} as the launcher
 * runs it, with the real core scorer): a bag dropped with its marker is scored with the topics of
 * the service configuration ({@code bags.metrics}), exactly once; a bag cut short is a failed run
 * with the reason; a bag without its marker (still being written) is left alone. The bags are
 * copies, in a temporary folder, of the recordings in ../shared/refdata/ros (the service moves
 * what it claims).
 */
class BareBagIntakeTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    /** Relative tolerance on evo's numbers (the core reproduces them to 1e-9, BagEvoParityTest). */
    private static final double REL_TOL = 1e-9;

    @TempDir
    Path root;

    private static Path ros() {
        Path dir = Paths.get(System.getProperty("trajeval.refdata", "../../shared/refdata")).resolve("ros");
        assertTrue(Files.isRegularFile(dir.resolve("evo_bag_reference.json")),
                "the ROS reference recordings must be at " + dir.toAbsolutePath() + " (../shared/refdata/ros)");
        return dir;
    }

    /** @return evo's statistic of a record of evo_bag_reference.json */
    private static double evo(String record, String stat) throws IOException {
        for (JsonNode r : JSON.readTree(ros().resolve("evo_bag_reference.json").toFile()).get("records")) {
            if (r.get("name").asText().equals(record)) {
                return r.get("stats").get(stat).asDouble();
            }
        }
        throw new AssertionError("no record " + record);
    }

    private int drain(StringWriter out, String... more) {
        CommandLine cl = PipelineCommand.newCommandLine(c -> new CoreRunScorer(c.limits().maxFileBytes()), Map.of());
        cl.setOut(new PrintWriter(out, true));
        cl.setErr(new PrintWriter(out, true));
        List<String> args = new ArrayList<>(List.of("watch", "--root", root.toString(), "--drain", "--no-http"));
        args.addAll(Arrays.asList(more));
        return cl.execute(args.toArray(String[]::new));
    }

    private Path config(String yaml) throws IOException {
        Path c = root.resolveSibling(root.getFileName() + "-config.yaml");
        Files.writeString(c, yaml);
        return c;
    }

    private static final String NAV2_CONFIG = "bags:\n  metrics:\n    ref_topic: /amcl_pose\n    est_topic: /odom\n"
            + "    alignment: se3\n";

    private Path incoming() throws IOException {
        return Files.createDirectories(root.resolve("incoming"));
    }

    private static long entries(Path dir) throws IOException {
        try (Stream<Path> s = Files.list(dir)) {
            return s.count();
        }
    }

    @Test
    void bareMcapWithMarkerIsScoredOnceWithTheConfiguredTopicsAsEvoScoresIt() throws IOException {
        Path cfg = config(NAV2_CONFIG);
        Files.copy(ros().resolve("nav2_turtlebot.mcap"), incoming().resolve("nav2-r1.mcap"));
        Files.writeString(incoming().resolve("nav2-r1.done"), "");
        StringWriter out = new StringWriter();
        assertEquals(0, drain(out, "--config", cfg.toString()), out.toString());
        assertTrue(out.toString().contains("reported=1 duplicates=0 failed=0"), out.toString());
        JsonNode report = JSON.readTree(root.resolve("reports/nav2-r1.json").toFile());
        assertEquals("nav2-r1", report.get("run_id").asText());
        // evo_ape bag2 nav2_turtlebot.mcap /amcl_pose /odom -a (evo 1.38.1, evo_bag_reference.json)
        double evoRmse = evo("mcap_odom_amcl_ape_se3", "rmse");
        double rmse = report.get("evaluation").get("ate").get("trans_m").get("rmse").asDouble();
        assertEquals(evoRmse, rmse, REL_TOL * evoRmse);
        assertEquals(report.get("reference_sha256").asText(), report.get("estimate_sha256").asText(),
                "one bag is both inputs");
        assertEquals(0, entries(root.resolve("incoming")));
        assertTrue(Files.isRegularFile(root.resolve("done/nav2-r1.mcap/nav2-r1.mcap")));

        // the same bag again (marker NAME.mcap.done this time): recognised, not reported twice
        Files.copy(ros().resolve("nav2_turtlebot.mcap"), incoming().resolve("nav2-r1.mcap"));
        Files.writeString(incoming().resolve("nav2-r1.mcap.done"), "");
        StringWriter again = new StringWriter();
        assertEquals(0, drain(again, "--config", cfg.toString()), again.toString());
        assertTrue(again.toString().contains("reported=0 duplicates=1 failed=0"), again.toString());
        assertFalse(Files.exists(root.resolve("reports/nav2-r1.v2.json")));
    }

    @Test
    void bareRos1BagTakesTopicsAndSettingsFromSetOverrides() throws IOException {
        Files.copy(ros().resolve("ROS_example.bag"), incoming().resolve("kitti00.bag"));
        Files.writeString(incoming().resolve("kitti00.done"), "");
        StringWriter out = new StringWriter();
        assertEquals(0, drain(out, "--set", "bags.metrics.ref_topic=groundtruth", "--set",
                "bags.metrics.est_topic=S-PTAM", "--set", "bags.metrics.alignment=se3"), out.toString());
        JsonNode report = JSON.readTree(root.resolve("reports/kitti00.json").toFile());
        // evo_ape bag ROS_example.bag groundtruth S-PTAM -a (evo_bag_reference.json)
        double evoRmse = evo("ros1_gt_sptam_ape_se3", "rmse");
        assertEquals(evoRmse, report.get("evaluation").get("ate").get("trans_m").get("rmse").asDouble(),
                REL_TOL * evoRmse);
    }

    @Test
    void bagCutShortIsAFailedRunWithTheReasonAndNothingIsLost() throws IOException {
        Path cfg = config(NAV2_CONFIG);
        byte[] whole = Files.readAllBytes(ros().resolve("nav2_turtlebot.mcap"));
        Files.write(incoming().resolve("cut.mcap"), Arrays.copyOf(whole, whole.length / 2));
        Files.writeString(incoming().resolve("cut.done"), "");
        StringWriter out = new StringWriter();
        assertEquals(4, drain(out, "--config", cfg.toString()), out.toString());
        assertTrue(out.toString().contains("reported=0 duplicates=0 failed=1"), out.toString());
        JsonNode err = JSON.readTree(root.resolve("failed/cut.mcap.error.json").toFile());
        assertEquals("corrupt_bag", err.get("kind").asText(), err.toString());
        assertTrue(err.get("bad_input").asBoolean());
        String message = err.get("message").asText();
        assertTrue(message.contains("cut.mcap") && message.contains("truncated"), message);
        assertFalse(message.contains("\n"), message);
        assertTrue(Files.isRegularFile(root.resolve("failed/cut.mcap/cut.mcap")), "the bag is kept beside its reason");
        assertFalse(Files.exists(root.resolve("reports/cut.json")));
    }

    @Test
    void bagWithoutMarkerOrStillChangingIsNotPickedUp() throws IOException {
        Path cfg = config(NAV2_CONFIG + "completion: marker_or_quiet\nquiet_time_s: 30\n");
        Path bag = incoming().resolve("writing.mcap");
        byte[] whole = Files.readAllBytes(ros().resolve("nav2_turtlebot.mcap"));
        Files.write(bag, Arrays.copyOf(whole, whole.length / 3)); // the recorder is still writing it
        StringWriter out = new StringWriter();
        assertEquals(0, drain(out, "--config", cfg.toString()), out.toString());
        assertTrue(out.toString().contains("reported=0 duplicates=0 failed=0"), out.toString());
        assertTrue(Files.isRegularFile(bag), "left in incoming/ while it changes");

        // finished, and quiet for longer than quiet_time_s: picked up without a marker
        Files.write(bag, whole);
        Files.setLastModifiedTime(bag, FileTime.from(Instant.now().minusSeconds(60)));
        StringWriter later = new StringWriter();
        assertEquals(0, drain(later, "--config", cfg.toString()), later.toString());
        assertTrue(later.toString().contains("reported=1 duplicates=0 failed=0"), later.toString());
        assertTrue(Files.isRegularFile(root.resolve("reports/writing.json")));
    }

    @Test
    void bagClaimedByAServiceThatDiedIsResumedAndReportedOnce() throws IOException {
        // a kill after the claim leaves processing/SLOT with the bag and its marker (its lock free)
        Path slot = Files.createDirectories(root.resolve("processing/r5.mcap"));
        Files.copy(ros().resolve("nav2_turtlebot.mcap"), slot.resolve("r5.mcap"));
        Files.writeString(slot.resolve("r5.done"), "");
        Files.writeString(slot.resolve(".lock"), "");
        StringWriter out = new StringWriter();
        assertEquals(0, drain(out, "--config", config(NAV2_CONFIG).toString()), out.toString());
        assertTrue(out.toString().contains("reported=1 duplicates=0 failed=0"), out.toString());
        assertTrue(Files.isRegularFile(root.resolve("reports/r5.json")));
        assertEquals(0, entries(root.resolve("processing")));
    }

    @Test
    void bareBagWithoutConfiguredTopicsIsRefusedNamingTheSettings() throws IOException {
        Files.copy(ros().resolve("nav2_turtlebot.mcap"), incoming().resolve("r9.mcap"));
        Files.writeString(incoming().resolve("r9.done"), "");
        StringWriter out = new StringWriter();
        assertEquals(4, drain(out), out.toString());
        JsonNode err = JSON.readTree(root.resolve("failed/r9.mcap.error.json").toFile());
        assertEquals("manifest", err.get("stage").asText());
        assertEquals("invalid_configuration", err.get("kind").asText());
        assertTrue(err.get("message").asText().contains("bags.metrics.ref_topic"), err.toString());
    }

    @Test
    void unknownTopicInTheConfigurationFailsTheRunListingTheBagsTopics() throws IOException {
        Files.copy(ros().resolve("nav2_turtlebot.mcap"), incoming().resolve("r10.mcap"));
        Files.writeString(incoming().resolve("r10.done"), "");
        StringWriter out = new StringWriter();
        assertEquals(4, drain(out, "--set", "bags.metrics.ref_topic=/amcl_pose", "--set",
                "bags.metrics.est_topic=/odm"), out.toString());
        JsonNode err = JSON.readTree(root.resolve("failed/r10.mcap.error.json").toFile());
        assertEquals("unknown_topic", err.get("kind").asText(), err.toString());
        assertTrue(err.get("message").asText().contains("/amcl_pose (geometry_msgs/msg/PoseWithCovarianceStamped)"),
                err.toString());
    }

    @Test
    void badBagSettingInTheConfigurationStopsTheStartWithOneLine() throws IOException {
        Path cfg = config("bags:\n  metrics:\n    ref_topic: /amcl_pose\n    est_topic: /odom\n    alignment: se4\n");
        StringWriter out = new StringWriter();
        assertEquals(2, drain(out, "--config", cfg.toString()));
        String line = out.toString().trim();
        assertFalse(line.contains("\n"), line);
        assertTrue(line.contains("bags.metrics.alignment") && line.contains("se4"), line);
    }
}
