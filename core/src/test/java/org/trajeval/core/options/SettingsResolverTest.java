package org.trajeval.core.options;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.PlanarProjection;
import org.trajeval.core.io.DuplicateTimestamps;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TimeUnit;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.RpeUnit;

/** The settings table and its resolver: the one path from text to options for every front end. */
class SettingsResolverTest {

    private static SettingValues file(String... kv) {
        Map<String, Object> tree = new LinkedHashMap<>();
        for (int i = 0; i < kv.length; i += 2) {
            tree.put(kv[i], kv[i + 1]);
        }
        return SettingValues.of(SettingsTree.flatten(tree, "metrics", "run.yaml"), "run.yaml");
    }

    @Test
    void tableHasUniqueSnakeCaseKeysAndDashedFlagsWithHelp() {
        Set<String> names = new HashSet<>();
        for (Setting s : Setting.values()) {
            assertTrue(s.key().matches("[a-z][a-z0-9_]*"), s.key());
            assertTrue(s.flag().matches("--[a-z][a-z0-9-]*"), s.flag());
            assertTrue(names.add(s.key()) && names.add(s.flag()), "duplicate " + s);
            assertTrue(s.help().endsWith("."), s + " help");
            assertTrue(s.unit().isEmpty() || s.key().endsWith("_" + s.unit()) || s.unit().equals("rpe_unit")
                    || s.kind() == SettingKind.PATH || s.kind() == SettingKind.INTEGER, s + " key names its unit");
        }
    }

    @Test
    void lessonPresetAlignsSe2OnPlanarDataAndSe3OnSpatialData() {
        assertEquals(AlignmentModel.SE2, SettingsResolver.evaluationOptions(SettingValues.DEFAULTS,
                DataKind.PLANAR).alignment());
        assertEquals(AlignmentModel.SE3, SettingsResolver.evaluationOptions(SettingValues.DEFAULTS,
                DataKind.SPATIAL).alignment());
        // planar projection makes SE(3) data planar: se2
        EvaluationOptions o = SettingsResolver.evaluationOptions(file("planar", "true"), DataKind.SPATIAL);
        assertEquals(AlignmentModel.SE2, o.alignment());
        assertEquals(PlanarProjection.XY_BEFORE_ALIGNMENT, o.projection());
    }

    @Test
    void evoConventionKeepsDuplicateStampsUnlessTold() {
        ReadOptions base = ReadOptions.defaults();
        assertEquals(DuplicateTimestamps.KEEP, SettingsResolver.readOptions(file("convention", "evo"),
                FileRole.REFERENCE, base, PathResolver.asWritten()).duplicates());
        assertEquals(DuplicateTimestamps.REFUSE, SettingsResolver.readOptions(file("convention", "evo",
                "duplicates", "refuse"), FileRole.REFERENCE, base, PathResolver.asWritten()).duplicates());
        assertEquals(DuplicateTimestamps.REFUSE, SettingsResolver.readOptions(SettingValues.DEFAULTS,
                FileRole.REFERENCE, base, PathResolver.asWritten()).duplicates());
    }

    @Test
    void perFileFormatAndTimesFileGoToTheirFileOnly() {
        SettingValues s = file("format", "tum", "ref_format", "euroc", "ref_times", "t.txt", "time_unit", "ns");
        ReadOptions ref = SettingsResolver.readOptions(s, FileRole.REFERENCE, ReadOptions.defaults(),
                (text, where) -> Path.of("/base").resolve(text));
        ReadOptions est = SettingsResolver.readOptions(s, FileRole.ESTIMATE, ReadOptions.defaults(),
                PathResolver.asWritten());
        assertEquals(TrajectoryFormat.EUROC, ref.format());
        assertEquals(TrajectoryFormat.TUM, est.format());
        assertEquals(Path.of("/base/t.txt"), ref.kittiTimes());
        assertNull(est.kittiTimes());
        assertEquals(TimeUnit.NS, est.csv().timeUnit());
    }

    @Test
    void nestedMappingIsShorthandForJoinedKeysAndNamesItsPath() {
        Map<String, Object> tree = new LinkedHashMap<>();
        tree.put("rpe", Map.of("delta", -1));
        InputException e = assertThrows(InputException.class,
                () -> SettingValues.of(SettingsTree.flatten(tree, "metrics", "suite.yaml"), "suite.yaml"));
        assertEquals("metrics.rpe.delta", e.column());
        assertEquals(InputProblem.INVALID_CONFIGURATION, e.problem());
        assertEquals("suite.yaml: 'metrics.rpe.delta' must be a number > 0, found \"-1\"", e.getMessage());
        Map<String, Object> lists = new LinkedHashMap<>();
        lists.put("drift", Map.of("segment_lengths_m", List.of(100, 200)));
        EvaluationOptions o = SettingsResolver.evaluationOptions(SettingValues.of(
                SettingsTree.flatten(lists, "metrics", "suite.yaml"), "suite.yaml"), DataKind.SPATIAL);
        assertArrayEquals(new double[] {100, 200}, o.drift().segmentLengthsM());
        assertEquals(10, o.drift().stepFrames());
    }

    @Test
    void unknownKeyIsRefusedWithTheKnownKeys() {
        InputException e = assertThrows(InputException.class, () -> file("max_dif_s", "0.1"));
        assertEquals("metrics.max_dif_s", e.column());
        assertTrue(e.getMessage().contains("expected one of format, ref_format"), e.getMessage());
        assertTrue(e.getMessage().contains("max_diff_s"), e.getMessage());
    }

    @Test
    void commandLineValuesAreRefusedAsOptionsNamingTheFlag() {
        InputException e = assertThrows(InputException.class, () -> SettingValues.of(
                List.of(new SettingText("alignment", "se4", "--align")), null));
        assertEquals(InputProblem.INVALID_OPTION, e.problem());
        assertEquals("--align must be one of none, se2, sim2, se3, sim3, origin, posyaw, found \"se4\"",
                e.getMessage());
    }

    @Test
    void badValuesAreRefusedWithTheExpectedForm() {
        for (String[] bad : new String[][] {{"max_diff_s", "0"}, {"max_diff_s", "NaN"}, {"t_offset_s", "1e999"},
            {"n_to_align", "0"}, {"n_to_align", "2.5"}, {"planar", "yes"}, {"columns", "t,x,y"},
            {"delimiter", ";;"}, {"drift_segment_lengths_m", "100,-1"}, {"rpe_unit", "deg"}, {"ref_times", " "}}) {
            InputException e = assertThrows(InputException.class, () -> file(bad[0], bad[1]), bad[0] + "=" + bad[1]);
            assertEquals("metrics." + bad[0], e.column());
        }
    }

    @Test
    void settingsThatExcludeEachOtherAreRefusedAtIntake() {
        assertThrows(InputException.class, () -> file("planar", "true", "project_to_plane", "xy"));
        assertThrows(InputException.class, () -> file("convention", "evo", "rpe_delta", "1.5"));
        assertThrows(InputException.class, () -> file("drift", "false", "drift_step_frames", "5"));
        assertThrows(InputException.class, () -> SettingValues.of(List.of(new SettingText("rpe_pairs",
                "consecutive", "--rpe-pairs"), new SettingText("rpe_pairs", "all-pairs", "--all-pairs")), null));
    }

    @Test
    void anRpeUnitWithoutDeltaMeansOneOfThatUnit() {
        EvaluationOptions o = SettingsResolver.evaluationOptions(file("rpe_unit", "m"), DataKind.PLANAR);
        assertEquals(RpeUnit.METRES, o.rpeUnit());
        assertEquals(1.0, o.rpeDelta(), 0.0);
        o = SettingsResolver.evaluationOptions(file("convention", "evo", "rpe_pairs", "all_pairs"), DataKind.PLANAR);
        assertEquals(PairSelection.ALL_PAIRS, o.pairSelection());
        assertEquals(RpeUnit.FRAMES, o.rpeUnit());
    }

    @Test
    void kittiDriftCanBeTurnedOff() {
        assertTrue(SettingsResolver.evaluationOptions(file("convention", "kitti"), DataKind.SPATIAL).drift() != null);
        assertNull(SettingsResolver.evaluationOptions(file("convention", "kitti", "drift", "false"),
                DataKind.SPATIAL).drift());
    }

    @Test
    void canonicalTextIsStableAndInTableOrder() {
        assertEquals("convention=evo;max_diff_s=0.02;rpe_unit=frames",
                file("rpe_unit", "FRAMES", "max_diff_s", "2e-2", "convention", "evo").canonical());
    }
}
