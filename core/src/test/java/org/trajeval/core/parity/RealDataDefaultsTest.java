package org.trajeval.core.parity;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.trajeval.core.RefData;
import org.trajeval.core.eval.Evaluator;
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

/** With default settings, real files give numbers a user can trust, and say what was left out. */
class RealDataDefaultsTest {

    private static EvaluationReport evaluate(String ref, String est, SettingText... settings) {
        Path dir = RefData.dir();
        SettingValues s = SettingValues.of(List.of(settings), null);
        LoadedTrajectory r = TrajectoryReader.read(dir.resolve(ref), SettingsResolver.readOptions(s,
                FileRole.REFERENCE, ReadOptions.defaults(), PathResolver.asWritten()));
        LoadedTrajectory e = TrajectoryReader.read(dir.resolve(est), SettingsResolver.readOptions(s,
                FileRole.ESTIMATE, ReadOptions.defaults(), PathResolver.asWritten()));
        return Evaluator.evaluate(r, e, SettingsResolver.evaluationOptions(s,
                DataKind.of(r.trajectory(), e.trajectory())));
    }

    /** @return first and last stamp of a TUM file (s) */
    private static double[] span(Path file) {
        try {
            List<String> rows = java.nio.file.Files.readAllLines(file).stream()
                    .filter(l -> !l.startsWith("#") && !l.isBlank()).toList();
            return new double[] {Double.parseDouble(rows.get(0).trim().split("\\s+")[0]),
                Double.parseDouble(rows.get(rows.size() - 1).trim().split("\\s+")[0])};
        } catch (java.io.IOException ex) {
            throw new java.io.UncheckedIOException(ex);
        }
    }

    @Test
    void fr2DeskOrbWithDefaultsIsNotInterpolatedAcrossTheTwelveSecondHole() {
        EvaluationReport r = evaluate("fr2_desk_groundtruth.txt", "fr2_desk_ORB.txt",
                new SettingText("duplicates", "keep", "--duplicates"));
        // evo_ape tum fr2_desk_groundtruth.txt fr2_desk_ORB.txt -a --sync_method interpolation --t_max_diff 0.02:
        // APE rmse 0.008113595170928087 m (../shared/refdata/evo_reference.json); with --t_max_diff 0.005:
        // 0.008026493077189282 m. Interpolating straight across the hole gave 0.1142 m.
        double evo = 0.008113595170928087;
        assertEquals(evo, r.ate().transM().rmse(), 0.03 * evo, "within 3 % of evo's figure");
        EvaluationReport.AssociationInfo a = r.association();
        assertTrue(a.droppedInGaps() > 300, "the 12 s hole holds ~360 ORB poses at 30 Hz: " + a.droppedInGaps());
        EvaluationReport.Gap longest = a.gaps().stream().max((x, y) -> Double.compare(x.lengthS(), y.lengthS()))
                .orElseThrow();
        // the hole of fr2_desk_groundtruth.txt: 1311868195.6081 -> 1311868207.5953 (read from the file)
        assertEquals(11.987, longest.lengthS(), 0.001);
        assertEquals("poses_dropped_in_reference_gaps", r.warnings().get(0).code());
        // the estimate misses that hole and more: the coverage shows it
        assertTrue(r.coverage().fraction() < 0.85, "coverage " + r.coverage().fraction());
        assertTrue(r.coverage().longestGapS() > 11.9, "longest stretch " + r.coverage().longestGapS());
    }

    @Test
    void fr1XyzDropsOnlyTheThreePosesOfItsOneLongGap() {
        EvaluationReport r = evaluate("freiburg1_xyz-groundtruth.txt", "freiburg1_xyz-rgbdslam.txt");
        // the ground truth is sampled every 0.01 s (median) and has one hole of 0.11 s (11 periods, above the
        // default 10); the 30 Hz estimate has 3 poses inside it. Nothing else is dropped.
        assertEquals(1, r.association().gaps().size());
        assertEquals(0.11, r.association().gaps().get(0).lengthS(), 0.001);
        assertEquals(3, r.association().droppedInGaps());
        // the 30 Hz estimate has no hole of its own: its coverage is the overlap of the two files' time spans
        // over the reference's span, from the first and last stamps of the two files
        double[] g = span(RefData.dir().resolve("freiburg1_xyz-groundtruth.txt"));
        double[] e = span(RefData.dir().resolve("freiburg1_xyz-rgbdslam.txt"));
        double overlap = (Math.min(g[1], e[1]) - Math.max(g[0], e[0])) / (g[1] - g[0]);
        assertEquals(overlap, r.coverage().fraction(), 0.005);
    }
}
