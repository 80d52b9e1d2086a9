package org.trajeval.core.parity;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.TestFactory;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.Evaluation;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.eval.PlanarProjection;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.stats.ErrorStatistics;

/**
 * Parity with evo 1.38.1: every record of ../shared/refdata/evo_reference.json (numbers computed
 * by evo itself, independent of this code) is recomputed through the same reader and evaluator
 * the CLI uses, and every statistic must agree within 1e-9 relative.
 */
class EvoParityTest {
    /** Relative tolerance of the parity claim. */
    static final double REL_TOL = 1e-9;
    /** Absolute tolerance for values near zero. */
    static final double ABS_TOL = 1e-12;

    private static final Map<String, LoadedTrajectory> CACHE = new HashMap<>();

    @TestFactory
    Stream<DynamicTest> everyEvoRecordIsReproduced() throws IOException {
        Path dir = refdata();
        JsonNode records = new ObjectMapper().readTree(dir.resolve("evo_reference.json").toFile());
        List<DynamicTest> tests = new ArrayList<>();
        int index = 0;
        for (JsonNode rec : records) {
            int id = index++;
            String name = String.format(Locale.ROOT, "#%04d %s vs %s %s", id, rec.get("ref").asText(),
                    rec.get("est").asText(), rec.get("options").toString());
            tests.add(DynamicTest.dynamicTest(name, () -> {
                CURRENT.set(name);
                check(dir, rec);
            }));
        }
        return tests.stream();
    }

    static Path refdata() {
        return org.trajeval.core.RefData.dir();
    }

    static synchronized LoadedTrajectory load(Path dir, String file, TrajectoryFormat format) {
        return CACHE.computeIfAbsent(file + "/" + format, k -> TrajectoryReader.read(dir.resolve(file),
                // evo keeps duplicate stamps (fr2_desk_groundtruth.txt, V102.txt have some): so do we here
                ReadOptions.defaults().withFormat(format).withDuplicates(DuplicateTimestamps.KEEP)));
    }

    /** The evo options of a record as trajeval options (the mapping the README's table states). */
    static EvaluationOptions options(JsonNode o, boolean forRpe) {
        EvaluationOptions opt = EvaluationOptions.preset(Convention.EVO);
        opt = opt.withAlignment(switch (o.get("align").asText()) {
            case "none" -> AlignmentModel.NONE;
            case "se3" -> AlignmentModel.SE3;
            case "sim3" -> AlignmentModel.SIM3;
            case "origin" -> AlignmentModel.ORIGIN;
            default -> throw new IllegalArgumentException(o.get("align").asText());
        });
        opt = opt.withMaxDiffS(o.get("t_max_diff").asDouble()).withTOffsetS(o.get("t_offset").asDouble());
        opt = opt.withAssociation("interpolation".equals(o.get("sync_method").asText())
                ? AssociationMethod.NEAREST_INTERPOLATED : AssociationMethod.NEAREST);
        opt = opt.withNToAlign(o.get("n_to_align").asInt());
        String plane = o.get("plane").isNull() ? null : o.get("plane").asText();
        if (plane != null) {
            boolean before = "before_align".equals(o.get("planar_order").asText());
            opt = opt.withProjection("xz".equals(plane) ? PlanarProjection.XZ_AFTER_ALIGNMENT
                    : before ? PlanarProjection.XY_BEFORE_ALIGNMENT : PlanarProjection.XY_AFTER_ALIGNMENT);
        }
        RpeUnit unit = "meters".equals(o.get("delta_unit").asText()) ? RpeUnit.METRES : RpeUnit.FRAMES;
        opt = opt.withRpe(o.get("delta").asDouble(), unit);
        opt = opt.withPairSelection(o.get("all_pairs").asBoolean() ? PairSelection.ALL_PAIRS : PairSelection.CONSECUTIVE);
        return opt;
    }

    private static void check(Path dir, JsonNode rec) {
        String format = rec.get("format").asText();
        TrajectoryFormat refFormat = switch (format) {
            case "tum" -> TrajectoryFormat.TUM;
            case "kitti" -> TrajectoryFormat.KITTI;
            case "euroc" -> TrajectoryFormat.EUROC;
            default -> throw new IllegalArgumentException(format);
        };
        TrajectoryFormat estFormat = "euroc".equals(format) ? TrajectoryFormat.TUM : refFormat;
        LoadedTrajectory ref = load(dir, rec.get("ref").asText(), refFormat);
        LoadedTrajectory est = load(dir, rec.get("est").asText(), estFormat);
        EvaluationOptions opt = options(rec.get("options"), false);
        if (rec.has("error")) {
            // evo: "found no matching timestamps": we refuse the pair the same way
            InputException e = assertThrows(InputException.class, () -> Evaluator.run(ref, est, opt));
            assertEquals(InputProblem.NO_OVERLAP, e.problem());
            return;
        }
        Evaluation ev = Evaluator.run(ref, est, opt);
        NOISE_FLOOR.set(noiseFloor(ref, est));
        String relation = rec.get("options").get("pose_relation").asText();
        assertEquals(rec.get("n_matched").asInt(), ev.associated().size(), "matched poses");
        compare("APE", rec.get("ape"), pick(relation, ev.ate().trans(), ev.ate().rot(), ev.ateFull()));
        compare("RPE", rec.get("rpe"), pick(relation, ev.rpe().trans(), ev.rpe().rot(), ev.rpeFull()));
        if (rec.has("alignment_scale") && "sim3".equals(rec.get("options").get("align").asText())) {
            assertClose("alignment scale", rec.get("alignment_scale").asDouble(), ev.alignment().scale(), 0.0);
        }
    }

    private static ErrorStatistics pick(String relation, ErrorStatistics trans, ErrorStatistics rot,
            ErrorStatistics full) {
        return switch (relation) {
            case "trans_part" -> trans;
            case "angle_deg" -> new ErrorStatistics(Math.toDegrees(rot.rmse()), Math.toDegrees(rot.mean()),
                    Math.toDegrees(rot.median()), Math.toDegrees(rot.std()), Math.toDegrees(rot.min()),
                    Math.toDegrees(rot.max()), rot.sse() * (180 / Math.PI) * (180 / Math.PI), rot.n());
            case "full" -> full;
            default -> throw new IllegalArgumentException(relation);
        };
    }

    private static void compare(String what, JsonNode expected, ErrorStatistics actual) {
        assertEquals(expected.get("n").asLong(), actual.n(), what + " n");
        double floor = NOISE_FLOOR.get();
        assertClose(what + " rmse", expected.get("rmse").asDouble(), actual.rmse(), floor);
        assertClose(what + " mean", expected.get("mean").asDouble(), actual.mean(), floor);
        assertClose(what + " median", expected.get("median").asDouble(), actual.median(), floor);
        // std subtracts nearly equal numbers: its rounding floor is ~1e-13 x |mean| (e.g. evo's
        // 180-degree flips after projecting before a 3D alignment: std 2e-14 deg at mean 180 deg)
        assertClose(what + " std", expected.get("std").asDouble(), actual.std(),
                Math.max(floor, 1e-13 * Math.abs(expected.get("mean").asDouble())));
        assertClose(what + " min", expected.get("min").asDouble(), actual.min(), floor);
        assertClose(what + " max", expected.get("max").asDouble(), actual.max(), floor);
        assertClose(what + " sse", expected.get("sse").asDouble(), actual.sse(), floor * floor);
    }

    /**
     * Rounding floor of a pair: 1e-15 x the largest coordinate magnitude (m), about 9 ulps of a
     * coordinate. Errors of exactly-equal trajectories (georeferenced.tum with itself, coordinates
     * ~5.4e6 m) are pure rounding noise of that size in evo (e.g. 4.6e-10 m) and in trajeval alike,
     * so below this floor values are compared absolutely. For every other pair the floor is below
     * 1e-12 and has no effect.
     */
    static double noiseFloor(LoadedTrajectory a, LoadedTrajectory b) {
        double max = 0;
        for (LoadedTrajectory l : new LoadedTrajectory[] {a, b}) {
            for (int i = 0; i < l.trajectory().size(); i++) {
                max = Math.max(max, Math.max(Math.abs(l.trajectory().x(i)),
                        Math.max(Math.abs(l.trajectory().y(i)), Math.abs(l.trajectory().z(i)))));
            }
        }
        return 1e-15 * max;
    }

    /** Absolute tolerance for records whose true value is 0 (see README: rounding floor). */
    static final ThreadLocal<String> CURRENT = ThreadLocal.withInitial(() -> "");

    static final ThreadLocal<Double> NOISE_FLOOR = ThreadLocal.withInitial(() -> ABS_TOL);

    /** Worst relative difference where the relative criterion governs (for the summary line). */
    private static double worstRelative;
    private static String worstWhat = "";
    private static int compared;

    @org.junit.jupiter.api.AfterAll
    static void printSummary() {
        System.out.printf(Locale.ROOT, "evo parity: %d statistics compared, worst relative difference %.3g (%s)%n",
                compared, worstRelative, worstWhat);
    }

    static synchronized void track(String what, double expected, double actual, double floor) {
        compared++;
        if (REL_TOL * Math.abs(expected) >= Math.max(ABS_TOL, floor)) {
            double rel = Math.abs(expected - actual) / Math.abs(expected);
            if (rel > worstRelative) {
                worstRelative = rel;
                worstWhat = what;
            }
        }
    }

    static void assertClose(String what, double expected, double actual, double absTol) {
        track(CURRENT.get() + " " + what, expected, actual, absTol);
        double tol = Math.max(Math.max(ABS_TOL, absTol), REL_TOL * Math.abs(expected));
        assertTrue(Math.abs(expected - actual) <= tol, () -> String.format(Locale.ROOT,
                "%s: evo %.17g, trajeval %.17g, difference %.3g > tolerance %.3g", what, expected, actual,
                Math.abs(expected - actual), tol));
    }
}
