package org.trajeval.cli;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Arrays;
import java.util.List;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.core.report.ResultSet;
import org.trajeval.core.report.SavedEvaluation;
import org.trajeval.core.report.SavedResults;
import org.trajeval.figures.EvalFigures;
import org.trajeval.figures.Figure;
import org.trajeval.figures.PlotPlane;

/**
 * {@code eval --plot / --save-series} and {@code res} on the real data of ../shared/refdata (KITTI
 * 00 with the ORB-SLAM and S-PTAM estimates, and evo's own --save_results archives of the same
 * pairs). Golden tests: they fail, not skip, when the data is missing.
 */
class PlotAndResOnRealDataTest {
    /** evo's and trajeval's per-pose errors agree to the alignment's floating-point noise (m). */
    private static final double SAME_ERROR_M = 1e-6;

    @TempDir
    static Path dir;
    private static Path refdata;

    @BeforeAll
    static void saveKittiOrb() {
        refdata = Paths.get(System.getProperty("trajeval.refdata", "../../shared/refdata"));
        assertTrue(Files.isRegularFile(refdata.resolve("evo_results/orb_ape.zip")),
                "../shared/refdata/evo_results is missing: " + refdata.toAbsolutePath());
        // evo's archives: APE with SE(3) Umeyama alignment; RPE over 10 m, consecutive pairs (info.json titles)
        CliRun r = CliRun.of("eval", refdata.resolve("KITTI_00_gt.txt").toString(),
                refdata.resolve("KITTI_00_ORB.txt").toString(), "--convention", "evo", "--align", "se3",
                "--rpe-delta", "10", "--rpe-unit", "m", "--drift", "--save-series", dir.resolve("orb").toString(),
                "--plot", dir.resolve("orb-plots").toString());
        assertEquals(0, r.code(), r.err());
    }

    @Test
    void kittiIsDrawnInXzAgainstFrames() {
        SavedEvaluation s = SavedEvaluation.read(dir.resolve("orb"));
        assertEquals("frame", s.series().timeUnit()); // KITTI has no stamps: frames, not "time (s)"
        List<Figure> figs = EvalFigures.of(s, PlotPlane.AUTO);
        assertEquals("z (m)", figs.get(0).y().label());
        assertEquals("frame", figs.get(1).x().label());
        assertTrue(figs.stream().anyMatch(f -> f.name().equals("drift_rot")));
        for (Figure f : figs) {
            assertTrue(Files.isRegularFile(dir.resolve("orb-plots/" + f.name() + ".svg")), f.name());
            assertTrue(Files.isRegularFile(dir.resolve("orb-plots/" + f.name() + ".png")), f.name());
        }
        assertTrue(Files.isRegularFile(dir.resolve("orb-plots/index.html")));
    }

    @Test
    void subTrajectoryErrorsAreSavedAtTenToFiftyPercentOfThePathAndDrawnByEvalAndRes() {
        SavedEvaluation s = SavedEvaluation.read(dir.resolve("orb"));
        double path = s.report().drift().pathLengthM(); // the reference's path length (m), as the drift saw it
        assertArrayEquals(new double[] {0.1 * path, 0.2 * path, 0.3 * path, 0.4 * path, 0.5 * path},
                s.series().segments().lengths(), 1e-9);
        assertTrue(Files.isRegularFile(dir.resolve("orb-plots/subtraj_trans.svg")));
        assertTrue(Files.isRegularFile(dir.resolve("orb-plots/subtraj_rot.png")));
        CliRun r = CliRun.of("res", "orb=" + dir.resolve("orb"),
                "evo=" + refdata.resolve("evo_results/orb_ape.zip"), "--plot", dir.resolve("res-sub").toString());
        assertEquals(0, r.code(), r.err());
        assertTrue(Files.isRegularFile(dir.resolve("res-sub/subtraj_trans.svg")));
    }

    @Test
    void givenSubTrajectoryLengthsAreTheOnesSaved() {
        CliRun r = CliRun.of("eval", refdata.resolve("KITTI_00_gt.txt").toString(),
                refdata.resolve("KITTI_00_SPTAM.txt").toString(), "--align", "se3", "--subtraj-lengths", "100,400",
                "--save-series", dir.resolve("sptam-lengths").toString());
        assertEquals(0, r.code(), r.err());
        assertArrayEquals(new double[] {100, 400},
                SavedEvaluation.read(dir.resolve("sptam-lengths")).series().segments().lengths());
    }

    @Test
    void plotFormatPdfWritesAVectorPagePerFigureInsteadOfPng() throws Exception {
        Path out = dir.resolve("pdf-plots");
        CliRun r = CliRun.of("eval", refdata.resolve("KITTI_00_gt.txt").toString(),
                refdata.resolve("KITTI_00_ORB.txt").toString(), "--align", "se3", "--plot", out.toString(),
                "--plot-format", "pdf,svg");
        assertEquals(0, r.code(), r.err());
        byte[] pdf = Files.readAllBytes(out.resolve("trajectories.pdf"));
        assertEquals("%PDF-1.4", new String(pdf, 0, 8, java.nio.charset.StandardCharsets.ISO_8859_1));
        assertTrue(Files.isRegularFile(out.resolve("subtraj_rot.pdf")));
        assertTrue(Files.isRegularFile(out.resolve("ate_trans.svg")));
        assertTrue(!Files.exists(out.resolve("ate_trans.png")));
        assertTrue(Files.readString(out.resolve("index.html")).contains("<a href=\"ate_trans.pdf\">PDF</a>"));
        CliRun bad = CliRun.of("eval", refdata.resolve("KITTI_00_gt.txt").toString(),
                refdata.resolve("KITTI_00_ORB.txt").toString(), "--plot", out.toString(), "--plot-format", "eps");
        assertEquals(ExitCodes.BAD_INPUT, bad.code(), bad.err());
        assertTrue(bad.err().contains("expected a comma list of svg, png and pdf, found \"eps\""), bad.err());
    }

    @Test
    void evoApeArchiveHoldsTrajevalsPerPoseErrors() {
        ResultSet evo = SavedResults.read(refdata.resolve("evo_results/orb_ape.zip"), "evo");
        ResultSet ours = SavedResults.read(dir.resolve("orb"), "trajeval");
        double[] a = evo.of(ResultSet.Kind.ATE_TRANS).values();
        double[] b = ours.of(ResultSet.Kind.ATE_TRANS).values();
        assertEquals(4541, a.length);
        assertArrayEquals(a, b, SAME_ERROR_M);
        assertEquals(1.3034497145650266, ours.of(ResultSet.Kind.ATE_TRANS).stats().rmse(), SAME_ERROR_M); // stats.json
    }

    @Test
    void evoRpeArchiveIsTrajevalsPairsWithoutTheFirst() {
        // The archive's evo (2018) starts its 10 m pairs at the first pose 10 m along the estimate's path,
        // not at pose 0: its 353 pairs are trajeval's 354 without the first (checked by hand: a pure
        // Python re-computation of evo's rule on these files matched the archive to 1e-13 m).
        double[] evo = SavedResults.read(refdata.resolve("evo_results/orb_rpe.zip"), "evo")
                .of(ResultSet.Kind.RPE_TRANS).values();
        double[] ours = SavedResults.read(dir.resolve("orb"), "trajeval").of(ResultSet.Kind.RPE_TRANS).values();
        assertEquals(353, evo.length);
        assertEquals(354, ours.length);
        assertArrayEquals(evo, Arrays.copyOfRange(ours, 1, ours.length), 1e-9);
    }

    @Test
    void resTablesPutEvoAndTrajevalSideBySide() throws Exception {
        CliRun r = CliRun.of("res", "evo=" + refdata.resolve("evo_results/orb_ape.zip"),
                "trajeval=" + dir.resolve("orb"), "--plot", dir.resolve("res").toString());
        assertEquals(0, r.code(), r.err());
        List<String> ate = r.out().lines().filter(l -> l.matches("(evo|trajeval) .*")).limit(2).toList();
        assertEquals(2, ate.size(), r.out());
        // same RMSE, mean, median, std, min and max to the 6 digits shown
        assertEquals(ate.get(0).replaceFirst("^evo\\s+evo\\s+", ""),
                ate.get(1).replaceFirst("^trajeval\\s+trajeval\\s+", ""));
        assertTrue(Files.isRegularFile(dir.resolve("res/res_ate_trans_box.svg")));
        String md = CliRun.of("res", dir.resolve("orb").toString(), "--format", "markdown").out();
        assertTrue(md.contains("| orb | trajeval | 1.30345 |"), md);
        String tex = CliRun.of("res", "my_run=" + dir.resolve("orb"), "--format", "latex").out();
        assertTrue(tex.contains("my\\_run & trajeval & 1.30345"), tex);
        String csv = CliRun.of("res", dir.resolve("orb").toString(), "--format", "csv").out();
        assertTrue(csv.startsWith("name,origin,source,metric,rmse,mean,median,std,min,max,n\n"), csv);
    }

    @Test
    void seedsOfOneNameGetTheirSpread() {
        CliRun r = CliRun.of("res", "orb=" + dir.resolve("orb"),
                "orb=" + refdata.resolve("evo_results/orb_ape.zip"));
        assertTrue(r.out().contains("RMSE over the results of one name (seeds)"), r.out());
        assertTrue(r.out().lines().anyMatch(l -> l.matches("orb\\s+2\\s+1\\.30345 .*")), r.out());
    }

    @Test
    void aFileThatIsNoResultIsRefusedInOneLine() throws Exception {
        Path bad = dir.resolve("notes.txt");
        Files.writeString(bad, "hello\n");
        CliRun r = CliRun.of("res", bad.toString());
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        assertEquals(1, r.err().strip().lines().count(), r.err());
        assertTrue(r.err().contains("notes.txt: a --save-series folder, an eval --out .json or an evo"), r.err());
        Path zip = dir.resolve("fake.zip");
        Files.writeString(zip, "not a zip");
        CliRun z = CliRun.of("res", zip.toString());
        assertEquals(ExitCodes.BAD_INPUT, z.code());
        assertTrue(z.err().contains("fake.zip: not a zip archive or empty"), z.err());
    }

    @Test
    void compareOnEvaluationReportsPointsToResInsteadOfLeakingAParserMessage() throws Exception {
        Path json = dir.resolve("orb.json");
        Files.copy(dir.resolve("orb/report.json"), json);
        CliRun r = CliRun.of("compare", json.toString(), json.toString());
        assertEquals(ExitCodes.BAD_INPUT, r.code());
        assertTrue(r.err().contains("orb.json: an evaluation report (trajeval eval --out), not a suite report; "
                + "trajeval res compares evaluation results"), r.err());
        assertTrue(!r.err().contains("deserialize"), r.err());
    }
}
