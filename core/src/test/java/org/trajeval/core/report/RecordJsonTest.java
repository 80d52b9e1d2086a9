package org.trajeval.core.report;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.annotation.JsonProperty;
import com.fasterxml.jackson.annotation.JsonPropertyOrder;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.trajeval.core.RefData;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.MaxGap;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.eval.TimeOffset;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryFormat;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.metric.RpeUnit;

/**
 * The streaming report writer writes, byte for byte, what the Jackson mapper writes (the
 * reference: {@link ReportJson#mapperJson}), for reports of every section and for non-finite and
 * missing values; types it cannot write that way go to the mapper.
 */
class RecordJsonTest {

    private static void assertWrittenAsTheMapperWrites(Object report) {
        assertTrue(RecordJson.supports(report.getClass()), report.getClass().getName());
        assertEquals(ReportJson.mapperJson(report), RecordJson.write(report));
        assertEquals(ReportJson.mapperJson(report), ReportJson.toJson(report));
    }

    @Test
    void evaluationReportsOfRealDataAreWrittenAsTheMapperWritesThem() {
        Path dir = RefData.dir();
        ReadOptions tum = ReadOptions.defaults().withFormat(TrajectoryFormat.TUM);
        LoadedTrajectory gt = TrajectoryReader.read(dir.resolve("freiburg1_xyz-groundtruth.txt"), tum);
        LoadedTrajectory orb = TrajectoryReader.read(dir.resolve("freiburg1_xyz-ORB_kf_mono.txt"), tum);
        LoadedTrajectory rgbd = TrajectoryReader.read(dir.resolve("freiburg1_xyz-rgbdslam.txt"), tum);
        ReadOptions kitti = ReadOptions.defaults().withFormat(TrajectoryFormat.KITTI);
        LoadedTrajectory kgt = TrajectoryReader.read(dir.resolve("KITTI_00_gt.txt"), kitti);
        LoadedTrajectory korb = TrajectoryReader.read(dir.resolve("KITTI_00_ORB.txt"), kitti);
        List<EvaluationReport> reports = new ArrayList<>();
        reports.add(Evaluator.evaluate(gt, orb, EvaluationOptions.preset(Convention.EVO).withAlignment(AlignmentModel.SIM3)));
        reports.add(Evaluator.evaluate(gt, rgbd, EvaluationOptions.preset(Convention.EVO)
                .withAssociation(AssociationMethod.INTERPOLATE).withExtraMetrics(true)
                .withTimeOffset(TimeOffset.AUTO).withMaxGap(MaxGap.ofSeconds(0.02))));
        reports.add(Evaluator.evaluate(gt, orb, EvaluationOptions.preset(Convention.LESSON).withRpe(1, RpeUnit.SECONDS)));
        reports.add(Evaluator.evaluate(kgt, korb, EvaluationOptions.preset(Convention.KITTI).withExtraMetrics(true)));
        for (EvaluationReport r : reports) {
            assertWrittenAsTheMapperWrites(r);
        }
        // the sections these reports exercise (else the comparison above proves less than it claims)
        assertTrue(reports.get(1).extra() != null, "extra");
        assertTrue(reports.get(1).association().tOffsetAuto() != null, "t_offset_auto");
        assertFalse(reports.get(1).association().gaps().isEmpty(), "gaps");
        assertFalse(reports.get(3).drift().perLength().isEmpty(), "drift");
        assertTrue(reports.stream().anyMatch(r -> !r.warnings().isEmpty()), "warnings");
    }

    @Test
    void nonFiniteAndMissingValuesAreWrittenAsTheMapperWritesThem() {
        EvaluationReport.Stats odd = new EvaluationReport.Stats(Double.NaN, Double.POSITIVE_INFINITY, null, -0.0,
                Double.MIN_VALUE, 1e300, 0.1 + 0.2, Long.MAX_VALUE);
        EvaluationReport r = new EvaluationReport(EvaluationReport.SCHEMA, EvaluationReport.SCHEMA_VERSION, "v \"q\"\n",
                null, new EvaluationReport.Inputs(new EvaluationReport.InputInfo("a\u00e9\u2028.csv", "csv", null, 3, "ab"),
                        new EvaluationReport.InputInfo("b", null, "\t", 0, null)),
                new EvaluationReport.AssociationInfo("nearest", 1, 2, 3, Double.NaN, -1.5, null, 0, null, Double.NaN, null,
                        0, List.of(), null),
                new EvaluationReport.AlignmentInfo("se3", new double[][] {{Double.NaN, 1}, {}}, new double[] {1e-320},
                        Double.NEGATIVE_INFINITY, 0),
                new EvaluationReport.Ate(odd, EvaluationReport.Stats.of(org.trajeval.core.stats.ErrorStatistics.of(
                        new double[0], 0))),
                null, new EvaluationReport.Drift(null, null, 0, 0, List.of(new EvaluationReport.DriftAtLength(100, null,
                        Double.NaN, 0)), 12.5),
                null, List.of(new EvaluationReport.Warning("w", null)), null, null);
        assertWrittenAsTheMapperWrites(r);
    }

    @JsonPropertyOrder({"a"})
    public record WithGetter(@JsonProperty("a") int a) {
        public int getB() {
            return 2; // Jackson writes it as "b"
        }
    }

    @JsonPropertyOrder({"a"})
    public record PartialOrder(@JsonProperty("a") int a, @JsonProperty("b") int b) {
    }

    public record NoOrder(@JsonProperty("a") int a) {
    }

    @JsonPropertyOrder({"a"})
    public record OtherValue(@JsonProperty("a") java.util.Set<String> a) {
    }

    @JsonPropertyOrder({"a"})
    public record NumberKeys(@JsonProperty("a") java.util.Map<Integer, String> a) {
    }

    @Test
    void mapsOfTextKeysAreWrittenAsTheMapperWritesThem() {
        // the pipeline report's tags (text) and factors (numbers) in insertion and sorted order, an empty map,
        // a null entry, non-finite numbers (null, ReportJson's rule) and a map left out under NON_NULL
        java.util.Map<String, String> tags = new java.util.LinkedHashMap<>();
        tags.put("z", "last \"q\"");
        tags.put("a", null);
        tags.put("m\u00e9", "");
        java.util.Map<String, Double> factors = new java.util.TreeMap<>(java.util.Map.of("b", 0.1 + 0.2, "a", -0.0,
                "c", Double.NaN, "d", Double.NEGATIVE_INFINITY, "e", 1e300));
        for (MapsRecord r : List.of(new MapsRecord(tags, factors, java.util.Map.of(), java.util.Map.of("k", List.of(1L, 2L))),
                new MapsRecord(null, new java.util.TreeMap<>(java.util.Map.of("x", 4.0)), null, null))) {
            assertTrue(RecordJson.supports(r.getClass()));
            assertWrittenAsTheMapperWrites(r);
        }
    }

    @Test
    void seededHostileTextAndNumbersAreWrittenAsTheMapperWritesThem() {
        // run names, tags and factors as a pipeline report carries them: control characters, quotes, backslashes,
        // U+2028/2029, DEL, NUL, lone surrogates, non-BMP characters; numbers of any bit pattern, -0.0, subnormals,
        // non-finite; null entries (rt9: no difference found, kept as a guard)
        java.util.Random rnd = new java.util.Random(20261126L);
        for (int i = 0; i < 3000; i++) {
            java.util.Map<String, String> tags = new java.util.LinkedHashMap<>();
            java.util.Map<String, Double> factors = new java.util.LinkedHashMap<>();
            for (int k = rnd.nextInt(4); k > 0; k--) {
                tags.put(hostile(rnd), rnd.nextInt(5) == 0 ? null : hostile(rnd));
                factors.put(hostile(rnd), rnd.nextInt(5) == 0 ? null : anyDouble(rnd));
            }
            assertWrittenAsTheMapperWrites(new MapsRecord(tags, factors, rnd.nextBoolean() ? null
                    : java.util.Map.of(hostile(rnd), hostile(rnd)), null));
            assertWrittenAsTheMapperWrites(new EvaluationReport.InputInfo(hostile(rnd), hostile(rnd),
                    rnd.nextBoolean() ? null : hostile(rnd), rnd.nextInt(), rnd.nextBoolean() ? null : hostile(rnd)));
        }
    }

    private static String hostile(java.util.Random rnd) {
        StringBuilder b = new StringBuilder();
        for (int i = rnd.nextInt(8); i > 0; i--) {
            switch (rnd.nextInt(6)) {
                case 0 -> b.append((char) rnd.nextInt(0x80));
                case 1 -> b.append((char) rnd.nextInt(0x10000)); // lone surrogates included
                case 2 -> b.appendCodePoint(0x10000 + rnd.nextInt(0x100000));
                case 3 -> b.append("\u2028\u2029\"\\/\u007f\u0000\t\r\n".charAt(rnd.nextInt(10)));
                default -> b.append((char) ('a' + rnd.nextInt(26)));
            }
        }
        return b.toString();
    }

    private static double anyDouble(java.util.Random rnd) {
        double[] odd = {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, -0.0, 0.0, Double.MIN_VALUE,
            Double.MAX_VALUE, 1e-7, 1e7, 0.1 + 0.2};
        return rnd.nextBoolean() ? odd[rnd.nextInt(odd.length)] : Double.longBitsToDouble(rnd.nextLong());
    }

    @Test
    void typesOutsideItsRulesGoToTheMapper() {
        for (Object o : new Object[] {new WithGetter(1), new PartialOrder(1, 2), new NoOrder(1),
            new OtherValue(java.util.Set.of("x")), new NumberKeys(java.util.Map.of(1, "x")), List.of(1)}) {
            assertFalse(RecordJson.supports(o.getClass()), o.getClass().getName());
            assertEquals(ReportJson.mapperJson(o), ReportJson.toJson(o));
        }
    }
}
