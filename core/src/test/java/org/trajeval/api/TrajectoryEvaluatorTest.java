package org.trajeval.api;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.report.EvaluationReport;

class TrajectoryEvaluatorTest {
    private static final double POSITION_TOL_M = 1e-9;
    private static final double EVO_RELATIVE_TOL = 1e-9;

    @Test
    void filesScoredWithEvoRulesGiveEvosOwnNumbers() throws IOException {
        // evo 1.38.1's evo_ape/evo_rpe on fr1_xyz rgbdslam, -a (se3), nearest stamps, 1 frame, trans_part
        Path dir = Paths.get(System.getProperty("trajeval.refdata", "../../shared/refdata"));
        Path reference = dir.resolve("evo_reference.json");
        assertTrue(Files.isRegularFile(reference), "the evo reference data must be present: " + reference);
        JsonNode record = null;
        for (JsonNode r : new ObjectMapper().readTree(reference.toFile())) {
            JsonNode o = r.get("options");
            if (r.get("ref").asText().equals("freiburg1_xyz-groundtruth.txt")
                    && r.get("est").asText().equals("freiburg1_xyz-rgbdslam.txt")
                    && o.get("align").asText().equals("se3") && o.get("sync_method").asText().equals("nearest_time")
                    && o.get("delta").asDouble() == 1.0 && o.get("delta_unit").asText().equals("frames")
                    && o.get("pose_relation").asText().equals("trans_part")) {
                record = r;
                break;
            }
        }
        assertTrue(record != null, "evo_reference.json has the fr1_xyz rgbdslam se3 record");

        TrajectoryEvaluator evaluator = TrajectoryEvaluator.of(Map.of("convention", "evo", "alignment", "se3"));
        EvaluationReport report = evaluator.evaluate(dir.resolve("freiburg1_xyz-groundtruth.txt"),
                dir.resolve("freiburg1_xyz-rgbdslam.txt"));

        double evoAte = record.get("ape").get("rmse").asDouble();
        double evoRpe = record.get("rpe").get("rmse").asDouble();
        assertEquals(evoAte, report.ate().transM().rmse(), EVO_RELATIVE_TOL * evoAte);
        assertEquals(evoRpe, report.rpe().transM().rmse(), EVO_RELATIVE_TOL * evoRpe);
        assertEquals(record.get("n_matched").asInt(), report.association().matched());
        assertEquals("tum", report.inputs().reference().format());
    }

    @Test
    void arraysScoreExactlyLikeTheSameDataReadFromAFile(@TempDir Path tmp) throws IOException {
        double[][] ref = curvedPlanarPath(400, new Random(11), 0.0, 0.0);
        double[][] est = curvedPlanarPath(400, new Random(12), 0.02, 0.3);
        Path refFile = writeCsv(tmp.resolve("ref.csv"), ref);
        Path estFile = writeCsv(tmp.resolve("est.csv"), est);
        TrajectoryEvaluator evaluator = TrajectoryEvaluator.withDefaults();

        EvaluationReport fromFiles = evaluator.evaluate(refFile, estFile);
        EvaluationReport fromArrays = evaluator.evaluate(Poses.planar("truth", ref[0], ref[1], ref[2], ref[3]),
                Poses.planar("run 7", est[0], est[1], est[2], est[3]));

        assertEquals(fromFiles.ate(), fromArrays.ate());
        assertEquals(fromFiles.rpe(), fromArrays.rpe());
        assertEquals(fromFiles.association(), fromArrays.association());
        assertEquals("se2", fromArrays.alignment().model());
        EvaluationReport.InputInfo in = fromArrays.inputs().estimate();
        assertEquals("run 7", in.path());
        assertEquals(TrajectoryEvaluator.MEMORY_FORMAT, in.format());
        assertEquals(400, in.poses());
        assertNull(in.sha256());
    }

    @Test
    void uniformOffsetWithoutAlignmentGivesAteEqualToTheOffset() {
        // every estimated pose is 0.10 m to the left (+y) of the truth: ATE-RMSE = 0.10 m by hand
        double[][] ref = curvedPlanarPath(200, new Random(3), 0.0, 0.0);
        double[] shiftedY = ref[2].clone();
        for (int i = 0; i < shiftedY.length; i++) {
            shiftedY[i] += 0.10;
        }
        TrajectoryEvaluator evaluator = TrajectoryEvaluator.of(Map.of("alignment", "none"));
        EvaluationReport r = evaluator.evaluate(Poses.planar("ref", ref[0], ref[1], ref[2], ref[3]),
                Poses.planar("est", ref[0], ref[1], shiftedY, ref[3]));
        assertEquals(0.10, r.ate().transM().rmse(), POSITION_TOL_M);
        assertEquals(0.10, r.ate().transM().max(), POSITION_TOL_M);
    }

    @Test
    void lessonConventionAlignsSpatialDataInThreeDimensionsLikeTheCommandLine() {
        // the estimate is the reference turned by 0.3 rad about the x axis and shifted by (1, 2, 3) m:
        // the lesson's preset for SE(3) data fits se3, which removes that motion exactly (ATE 0)
        int n = 120;
        double[] t = new double[n], x = new double[n], y = new double[n], z = new double[n];
        double[] ex = new double[n], ey = new double[n], ez = new double[n];
        double[] qw = new double[n], qx = new double[n], qy = new double[n], qz = new double[n];
        double[] eqw = new double[n], eqx = new double[n], eqy = new double[n], eqz = new double[n];
        double c = Math.cos(0.3), s = Math.sin(0.3);
        double hw = Math.cos(0.15), hx = Math.sin(0.15); // the same turn as a quaternion (w, x, 0, 0)
        for (int i = 0; i < n; i++) {
            t[i] = 0.1 * i;
            x[i] = Math.cos(0.05 * i) * 3;
            y[i] = Math.sin(0.05 * i) * 3;
            z[i] = 0.2 * Math.sin(0.11 * i);
            double yaw = 0.05 * i;
            qw[i] = Math.cos(yaw / 2);
            qz[i] = Math.sin(yaw / 2);
            ex[i] = x[i] + 1;
            ey[i] = c * y[i] - s * z[i] + 2;
            ez[i] = s * y[i] + c * z[i] + 3;
            // q_est = q_turn * q_ref, with q_turn = (hw, hx, 0, 0) and q_ref = (qw, 0, 0, qz)
            eqw[i] = hw * qw[i];
            eqx[i] = hx * qw[i];
            eqy[i] = -hx * qz[i];
            eqz[i] = hw * qz[i];
        }
        EvaluationReport r = TrajectoryEvaluator.withDefaults().evaluate(
                Poses.spatial("ref", t, x, y, z, qw, qx, qy, qz), Poses.spatial("est", t, ex, ey, ez, eqw, eqx, eqy, eqz));
        assertEquals("se3", r.alignment().model());
        assertEquals(0.0, r.ate().transM().rmse(), POSITION_TOL_M);
        assertEquals(0.0, r.ate().rotRad().rmse(), 1e-9);
    }

    @Test
    void oneEvaluatorScoresManyPairsFromManyThreadsAtOnce() throws Exception {
        TrajectoryEvaluator evaluator = TrajectoryEvaluator.withDefaults();
        double[][] ref = curvedPlanarPath(3000, new Random(5), 0.0, 0.0);
        List<Poses> estimates = new ArrayList<>();
        List<EvaluationReport> sequential = new ArrayList<>();
        Poses truth = Poses.planar("ref", ref[0], ref[1], ref[2], ref[3]);
        for (int k = 0; k < 8; k++) {
            double[][] e = curvedPlanarPath(3000, new Random(100 + k), 0.01 * (k + 1), 0.1 * k);
            estimates.add(Poses.planar("est" + k, e[0], e[1], e[2], e[3]));
            sequential.add(evaluator.evaluate(truth, estimates.get(k)));
        }
        ExecutorService pool = Executors.newFixedThreadPool(4);
        try {
            List<Future<EvaluationReport>> futures = new ArrayList<>();
            for (int round = 0; round < 3; round++) {
                for (Poses e : estimates) {
                    futures.add(pool.submit(() -> evaluator.evaluate(truth, e)));
                }
            }
            for (int i = 0; i < futures.size(); i++) {
                EvaluationReport got = futures.get(i).get();
                EvaluationReport want = sequential.get(i % estimates.size());
                assertEquals(want.ate(), got.ate());
                assertEquals(want.rpe(), got.rpe());
            }
        } finally {
            pool.shutdownNow();
        }
    }

    @Test
    void aBadFileIsRefusedWithItsLineAndColumn(@TempDir Path tmp) throws IOException {
        Path ref = writeCsv(tmp.resolve("ref.csv"), curvedPlanarPath(10, new Random(1), 0.0, 0.0));
        Path bad = tmp.resolve("bad.csv");
        Files.writeString(bad, "t,x,y,yaw\n0.0,0,0,0\n0.1,0,0,nan\n");
        InputException e = assertThrows(InputException.class,
                () -> TrajectoryEvaluator.withDefaults().evaluate(ref, bad));
        assertEquals(bad.toString(), e.source());
        assertEquals(3, e.line());
        assertEquals("yaw", e.column());
        assertEquals(InputProblem.NOT_FINITE, e.problem());
    }

    @Test
    void poseArraysOfDifferentLengthsAreRefused() {
        double[] three = {0, 1, 2};
        double[] two = {0, 1};
        assertThrows(IllegalArgumentException.class, () -> Poses.planar("p", three, three, two, three));
        assertThrows(IllegalArgumentException.class, () -> Poses.planar(" ", three, three, three, three));
    }

    @Test
    void settingsAreTheCommandLinesAndRunYamlsNestedOrFlat(@TempDir Path tmp) throws IOException {
        // the same RPE horizon written flat, nested (as in run.yaml) and with a number value
        double[][] ref = curvedPlanarPath(300, new Random(8), 0.0, 0.0);
        double[][] est = curvedPlanarPath(300, new Random(9), 0.03, 0.2);
        Poses truth = Poses.planar("ref", ref[0], ref[1], ref[2], ref[3]);
        Poses run = Poses.planar("est", est[0], est[1], est[2], est[3]);
        EvaluationReport flat = TrajectoryEvaluator.of(Map.of("rpe_delta", "5", "rpe_unit", "frames"))
                .evaluate(truth, run);
        EvaluationReport nested = TrajectoryEvaluator.of(Map.of("rpe", Map.of("delta", 5, "unit", "frames")))
                .evaluate(truth, run);
        assertEquals(flat.rpe(), nested.rpe());
        assertEquals("frames", flat.rpe().unit());
        assertEquals(5.0, flat.rpe().delta());
    }

    @Test
    void badSettingsAreRefusedNamingTheKey() {
        InputException unknown = assertThrows(InputException.class,
                () -> TrajectoryEvaluator.of(Map.of("alignmnet", "se3")));
        assertEquals(TrajectoryEvaluator.SETTINGS_SOURCE, unknown.source());
        assertEquals("alignmnet", unknown.column());
        assertEquals(InputProblem.INVALID_CONFIGURATION, unknown.problem());
        InputException outOfRange = assertThrows(InputException.class,
                () -> TrajectoryEvaluator.of(Map.of("max_diff_s", -1)));
        assertEquals("max_diff_s", outOfRange.column());
    }

    @Test
    void readingSettingsAreRefusedForArrays() {
        double[][] ref = curvedPlanarPath(20, new Random(1), 0.0, 0.0);
        Poses p = Poses.planar("ref", ref[0], ref[1], ref[2], ref[3]);
        InputException e = assertThrows(InputException.class,
                () -> TrajectoryEvaluator.of(Map.of("sort", true)).evaluate(p, p));
        assertEquals("sort", e.column());
        assertEquals(InputProblem.INVALID_CONFIGURATION, e.problem());
    }

    /** t, x, y, yaw of a seeded curved path (10 Hz), optionally offset in position noise and heading. */
    private static double[][] curvedPlanarPath(int n, Random rnd, double noiseM, double yawOffsetRad) {
        double[][] p = new double[4][n];
        for (int i = 0; i < n; i++) {
            p[0][i] = 100.0 + 0.1 * i;
            p[1][i] = 0.5 * i * Math.cos(0.002 * i) + noiseM * rnd.nextGaussian();
            p[2][i] = 0.5 * i * Math.sin(0.002 * i) + noiseM * rnd.nextGaussian();
            p[3][i] = 0.3 * Math.sin(0.01 * i) + yawOffsetRad;
        }
        return p;
    }

    /** Writes with 17 significant digits, so the file reads back to the same doubles. */
    private static Path writeCsv(Path file, double[][] p) throws IOException {
        StringBuilder sb = new StringBuilder("t,x,y,yaw\n");
        for (int i = 0; i < p[0].length; i++) {
            sb.append(String.format(Locale.ROOT, "%.17g,%.17g,%.17g,%.17g%n", p[0][i], p[1][i], p[2][i], p[3][i]));
        }
        return Files.writeString(file, sb.toString());
    }
}
