package org.trajeval.core.io.bag;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.Evaluation;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.stats.ErrorStatistics;

/**
 * Parity with evo 1.38.1 on real bags: every record of ../shared/refdata/ros/evo_bag_reference.json
 * (evo's own stats.json for the command in the record, computed by evo, not by us) is recomputed
 * from the bag by trajeval's bag readers and evaluator; every statistic must agree to 1e-9
 * relative. The records' commands are parsed (bag/bag2, file, two topics, -a, -s, --delta,
 * --delta_unit) and mapped to trajeval's evo convention, as the README's table states. Missing
 * reference data fails the test (it does not skip).
 */
class BagEvoParityTest {
    static final double REL_TOL = 1e-9;

    static Path rosData() {
        Path dir = Paths.get(System.getProperty("trajeval.refdata", "../../shared/refdata")).resolve("ros");
        assertTrue(Files.isRegularFile(dir.resolve("evo_bag_reference.json")),
                "evo bag reference data missing at " + dir.toAbsolutePath() + " (../shared/refdata/ros)");
        return dir;
    }

    @TestFactory
    Stream<DynamicTest> everyEvoBagRecordIsReproduced() throws IOException {
        Path dir = rosData();
        JsonNode records = new ObjectMapper().readTree(dir.resolve("evo_bag_reference.json").toFile()).get("records");
        List<DynamicTest> tests = new ArrayList<>();
        for (JsonNode rec : records) {
            tests.add(DynamicTest.dynamicTest(rec.get("name").asText() + ": " + rec.get("evo_cli").asText(),
                    () -> check(dir, rec)));
        }
        assertEquals(5, tests.size(), "records in evo_bag_reference.json");
        return tests.stream();
    }

    private static void check(Path dir, JsonNode rec) {
        List<String> cli = Arrays.asList(rec.get("evo_cli").asText().split("\\s+"));
        boolean rpe = cli.get(0).equals("evo_rpe");
        Path bag = dir.resolve(cli.get(2));
        ReadOptions read = ReadOptions.defaults().withDuplicates(DuplicateTimestamps.KEEP);
        LoadedTrajectory ref = BagTrajectoryReader.read(bag, BagReadOptions.of(cli.get(3)), read);
        LoadedTrajectory est = BagTrajectoryReader.read(bag, BagReadOptions.of(cli.get(4)), read);
        EvaluationOptions o = EvaluationOptions.preset(Convention.EVO);
        for (int i = 5; i < cli.size(); i++) {
            String a = cli.get(i);
            if (a.startsWith("-") && !a.startsWith("--")) {
                boolean align = a.contains("a");
                boolean scale = a.contains("s");
                o = o.withAlignment(align && scale ? AlignmentModel.SIM3 : align ? AlignmentModel.SE3
                        : AlignmentModel.NONE);
            } else if (a.equals("--delta")) {
                double delta = Double.parseDouble(cli.get(++i));
                RpeUnit unit = cli.contains("m") ? RpeUnit.METRES : RpeUnit.FRAMES;
                o = o.withRpe(delta, unit);
            }
        }
        Evaluation ev = Evaluator.run(ref, est, o);
        ErrorStatistics s = rpe ? ev.rpe().trans() : ev.ate().trans();
        JsonNode e = rec.get("stats");
        close("rmse", e.get("rmse").asDouble(), s.rmse());
        close("mean", e.get("mean").asDouble(), s.mean());
        close("median", e.get("median").asDouble(), s.median());
        close("std", e.get("std").asDouble(), s.std());
        close("min", e.get("min").asDouble(), s.min());
        close("max", e.get("max").asDouble(), s.max());
        close("sse", e.get("sse").asDouble(), s.sse());
    }

    private static void close(String what, double expected, double actual) {
        assertTrue(Math.abs(actual - expected) <= REL_TOL * Math.abs(expected),
                what + ": evo " + expected + ", trajeval " + actual + " (relative " + Math.abs(actual - expected)
                        / Math.abs(expected) + ")");
    }
}
