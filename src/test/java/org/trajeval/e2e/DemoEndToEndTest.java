package org.trajeval.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.cli.TrajevalCommand;
import picocli.CommandLine;

/**
 * The README's first command, {@code trajeval demo --out DIR}, in a temporary folder: every report
 * file is written, the JSON is reproducible, and the HTML page opens in headless Chromium with every
 * figure drawn, no console message and nothing fetched from the network; so does an eval --plot page.
 * Screenshots go to build/screenshots/.
 */
class DemoEndToEndTest {
    @TempDir
    static Path dir;
    private static String out;

    @BeforeAll
    static void demo() {
        StringWriter o = new StringWriter();
        StringWriter e = new StringWriter();
        CommandLine cl = TrajevalCommand.newCommandLine();
        cl.setOut(new PrintWriter(o));
        cl.setErr(new PrintWriter(e));
        int code = cl.execute("demo", "--out", dir.resolve("demo").toString());
        out = o.toString();
        assertEquals(0, code, e.toString());
    }

    @Test
    void demoWritesTheBenchmarkAndEveryReport() {
        Path report = dir.resolve("demo/report");
        for (String f : new String[] {"report.json", "runs.csv", "methods.csv", "comparisons.csv", "report.html"}) {
            assertTrue(Files.isRegularFile(report.resolve(f)), f);
        }
        assertTrue(Files.isRegularFile(dir.resolve("demo/benchmark/suite.yaml")));
        assertTrue(out.contains("LEAKAGE"), out);
        assertTrue(out.contains("alpha") && out.contains("beta") && out.contains("gamma"), out);
    }

    @Test
    void sameSeedGivesByteIdenticalJson() throws IOException {
        CommandLine cl = TrajevalCommand.newCommandLine();
        cl.setOut(new PrintWriter(new StringWriter()));
        cl.setErr(new PrintWriter(new StringWriter()));
        assertEquals(0, cl.execute("demo", "--out", dir.resolve("again").toString(), "--threads", "1"));
        assertEquals(Files.readString(dir.resolve("demo/report/report.json")),
                Files.readString(dir.resolve("again/report/report.json")));
    }

    @Test
    void demoReportShowsTheRankDiagramAndEffectSizes() throws IOException {
        Path report = dir.resolve("demo/report");
        String html = Files.readString(report.resolve("report.html"));
        for (String metric : new String[] {"ate_trans_rmse_m", "rpe_trans_rmse_m", "score"}) {
            String svg = Files.readString(report.resolve("ranks_" + metric + ".svg"));
            assertTrue(svg.startsWith("<svg") && html.contains(svg.strip()), metric);
        }
        assertTrue(html.contains("Hodges-Lehmann") && html.contains("Friedman") && html.contains("Holm p"), "sections");
        assertTrue(out.contains("Friedman chi2") && out.contains("Hodges-Lehmann"), out);
    }

    @Test
    void htmlIsSelfContained() throws IOException {
        String html = Files.readString(dir.resolve("demo/report/report.html"));
        assertFalse(Pattern.compile("(src|href)\\s*=\\s*\"(https?:)?//", Pattern.CASE_INSENSITIVE).matcher(html).find(),
                "the page must not fetch anything");
        Matcher m = Pattern.compile("<img src=\"data:image/svg\\+xml;base64,").matcher(html);
        int images = 0;
        while (m.find()) {
            images++;
        }
        assertEquals(4 + 2 * 8, images); // ATE/RPE translation/rotation boxes, overlay + error plot per test sequence
    }

    @Test
    void htmlOpensInHeadlessChromiumWithEveryFigureDrawnAndNoConsoleMessage() throws Exception {
        HeadlessChromium.assumeInstalled();
        HeadlessChromium.Result r = HeadlessChromium.open(dir.resolve("demo/report/report.html"), dir, "suite-report");
        assertEquals(20, r.images());
        assertEquals(0, r.broken(), "images that did not load");
        assertEquals(0, r.blank(), "figures without data: " + r.blankAlts());
        assertEquals(List.of(), r.console());
        assertTrue(Files.size(r.screenshot()) > 10_000, "screenshot " + r.screenshot());
    }

    @Test
    void evalPlotPageOpensInHeadlessChromiumWithEveryFigureDrawn() throws Exception {
        HeadlessChromium.assumeInstalled();
        Path refdata = Path.of(System.getProperty("trajeval.refdata", "../shared/refdata"));
        StringWriter e = new StringWriter();
        CommandLine cl = TrajevalCommand.newCommandLine();
        cl.setOut(new PrintWriter(new StringWriter()));
        cl.setErr(new PrintWriter(e));
        assertEquals(0, cl.execute("eval", refdata.resolve("freiburg1_xyz-groundtruth.txt").toString(),
                refdata.resolve("freiburg1_xyz-rgbdslam.txt").toString(), "--plot", dir.resolve("tum").toString()),
                e.toString());
        HeadlessChromium.Result r = HeadlessChromium.open(dir.resolve("tum/index.html"), dir, "eval-plot");
        assertEquals(11, r.images()); // trajectories, 4 over time, 4 histograms, 2 sub-trajectory box plots
        assertEquals(0, r.broken(), "images that did not load");
        assertEquals(0, r.blank(), "figures without data: " + r.blankAlts());
        assertEquals(List.of(), r.console());
        assertTrue(Files.size(r.screenshot()) > 10_000, "screenshot " + r.screenshot());
    }
}
