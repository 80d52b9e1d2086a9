package org.trajeval.core.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.RefData;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.options.DataKind;
import org.trajeval.core.options.FileRole;
import org.trajeval.core.options.PathResolver;
import org.trajeval.core.options.SettingText;
import org.trajeval.core.options.SettingValues;
import org.trajeval.core.options.SettingsResolver;
import org.trajeval.core.report.EvaluationReport;

/** Degenerate alignments are named in the report's warnings, with the option that avoids them. */
public class AlignmentWarningsTest {
    @TempDir
    Path dir;

    private static List<String> codes(EvaluationReport r) {
        return r.warnings().stream().map(EvaluationReport.Warning::code).toList();
    }

    /** Reads and evaluates a pair with settings given as key, value, ... (as the command line would). */
    public static EvaluationReport evaluate(Path ref, Path est, String... kv) {
        SettingText[] t = new SettingText[kv.length / 2];
        for (int i = 0; i < t.length; i++) {
            t[i] = new SettingText(kv[2 * i], kv[2 * i + 1], kv[2 * i]);
        }
        SettingValues s = SettingValues.of(List.of(t), null);
        LoadedTrajectory r = TrajectoryReader.read(ref, SettingsResolver.readOptions(s, FileRole.REFERENCE,
                ReadOptions.defaults(), PathResolver.asWritten()));
        LoadedTrajectory e = TrajectoryReader.read(est, SettingsResolver.readOptions(s, FileRole.ESTIMATE,
                ReadOptions.defaults(), PathResolver.asWritten()));
        return Evaluator.evaluate(r, e, SettingsResolver.evaluationOptions(s, DataKind.of(r.trajectory(),
                e.trajectory())));
    }

    @Test
    void se3OnFr2DeskProjectedToThePlaneFlipsItAndSaysSo() {
        Path d = RefData.dir();
        // evo's records of fr2_desk with -a and --project_to_plane xy before alignment show APE angles of
        // 180 deg at every pose (../shared/refdata/evo_reference.json): the fit mirrors the plane
        EvaluationReport flipped = evaluate(d.resolve("fr2_desk_groundtruth.txt"), d.resolve("fr2_desk_ORB.txt"),
                "duplicates", "keep", "planar", "true", "alignment", "se3");
        assertTrue(codes(flipped).contains("alignment_flips_plane"), codes(flipped).toString());
        assertTrue(flipped.warnings().get(0).message().contains("--align se2"), flipped.warnings().get(0).message());
        EvaluationReport proper = evaluate(d.resolve("fr2_desk_groundtruth.txt"), d.resolve("fr2_desk_ORB.txt"),
                "duplicates", "keep", "planar", "true");
        assertFalse(codes(proper).contains("alignment_flips_plane"), codes(proper).toString());
    }

    @Test
    void simAlignmentOfAMonocularEstimateNamesItsScale() {
        Path d = RefData.dir();
        EvaluationReport mono = evaluate(d.resolve("fr2_desk_groundtruth.txt"),
                d.resolve("fr2_desk_ORB_kf_mono.txt"), "duplicates", "keep", "alignment", "sim3");
        assertTrue(codes(mono).contains("alignment_scale_far_from_one"), "scale " + mono.alignment().scale());
        EvaluationReport metric = evaluate(d.resolve("freiburg1_xyz-groundtruth.txt"),
                d.resolve("freiburg1_xyz-rgbdslam.txt"), "alignment", "sim3");
        assertFalse(codes(metric).contains("alignment_scale_far_from_one"), "scale " + metric.alignment().scale());
    }

    @Test
    void se3OnAlmostCollinearPositionsSaysTheRotationIsNotDetermined() throws IOException {
        // a straight 10 m run along x with 1e-5 m of seeded noise across it: spread ratio ~ 3e-6 << 1e-3
        Random rnd = new Random(7);
        StringBuilder g = new StringBuilder();
        StringBuilder e = new StringBuilder();
        for (int i = 0; i < 200; i++) {
            double t = i * 0.05;
            double x = 0.05 * i;
            g.append(String.format(Locale.ROOT, "%.3f %.6f %.9f %.9f 0 0 0 1%n", t, x, 1e-5 * rnd.nextGaussian(),
                    1e-5 * rnd.nextGaussian()));
            e.append(String.format(Locale.ROOT, "%.3f %.6f %.9f %.9f 0 0 0 1%n", t, x + 1.0,
                    2.0 + 1e-5 * rnd.nextGaussian(), 1e-5 * rnd.nextGaussian()));
        }
        Path gt = dir.resolve("line_gt.txt");
        Path est = dir.resolve("line_est.txt");
        Files.write(gt, g.toString().getBytes(StandardCharsets.UTF_8));
        Files.write(est, e.toString().getBytes(StandardCharsets.UTF_8));
        EvaluationReport r = evaluate(gt, est, "alignment", "se3");
        assertTrue(codes(r).contains("alignment_rotation_unobservable"), codes(r).toString());
        EvaluationReport yawOnly = evaluate(gt, est, "alignment", "posyaw");
        assertFalse(codes(yawOnly).contains("alignment_rotation_unobservable"), codes(yawOnly).toString());
    }

    @Test
    void principalSpreadsOfAPlaneHaveAZeroThird() {
        // points on the unit square corners in the xy plane: covariance diag(0.25, 0.25, 0) by hand
        var p = org.trajeval.core.traj.PoseSequence.of(new double[] {0, 1, 0, 1}, new double[] {0, 0, 1, 1},
                new double[4], new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1,
                    1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1});
        double[] sd = AlignmentCheck.principalSpreads(p, 4);
        // the closed form loses digits when two eigenvalues coincide (acos near its ends): 1e-6 m is plenty
        // against the 1e-3 ratio the check uses
        assertEquals(0.5, sd[0], 1e-6);
        assertEquals(0.5, sd[1], 1e-6);
        assertEquals(0.0, sd[2], 1e-6);
    }
}
