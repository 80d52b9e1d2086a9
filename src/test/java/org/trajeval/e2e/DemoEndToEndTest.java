package org.trajeval.e2e;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.trajeval.cli.TrajevalCommand;
import picocli.CommandLine;

/**
 * The README's first command, {@code trajeval demo --out DIR}, in a temporary folder: every report
 * file is written, the JSON is reproducible, and the HTML page opens in headless Chromium with every
 * image loaded and nothing fetched from the network.
 */
class DemoEndToEndTest {
    private static final Path CHROMIUM = Path.of("/usr/bin/chromium");

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
        Matcher m = Pattern.compile("<img src=\"data:image/png;base64,").matcher(html);
        int images = 0;
        while (m.find()) {
            images++;
        }
        assertEquals(2 + 2 * 8, images); // two box plots, overlay + error plot per test sequence
    }

    @Test
    void htmlOpensInHeadlessChromiumWithEveryImageLoaded() throws Exception {
        Assumptions.assumeTrue(Files.isExecutable(CHROMIUM),
                "SKIPPED LOUDLY: /usr/bin/chromium is absent; run scripts/ensure-tools (apt-get install chromium)");
        String html = Files.readString(dir.resolve("demo/report/report.html"));
        // a copy with a probe that writes what the browser loaded into the DOM (the report has no script)
        String probe = "<script>window.addEventListener('load',function(){var imgs=document.images,bad=0;"
                + "for(var i=0;i<imgs.length;i++){if(!(imgs[i].complete&&imgs[i].naturalWidth>0))bad++;}"
                + "var p=document.createElement('pre');p.id='probe';p.textContent='images='+imgs.length+' broken='+bad;"
                + "document.body.appendChild(p);});</script></body>";
        Path page = dir.resolve("probe.html");
        Files.writeString(page, html.replace("</body>", probe));
        Process p = new ProcessBuilder(CHROMIUM.toString(), "--headless", "--no-sandbox", "--disable-gpu",
                "--user-data-dir=" + dir.resolve("chromium-profile"), "--virtual-time-budget=10000", "--dump-dom",
                page.toUri().toString()).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        String dom = new String(p.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "chromium did not finish");
        Matcher m = Pattern.compile("images=(\\d+) broken=(\\d+)").matcher(dom);
        assertTrue(m.find(), "probe result missing from the DOM");
        assertEquals(18, Integer.parseInt(m.group(1)));
        assertEquals(0, Integer.parseInt(m.group(2)), "images that did not load");
        assertTrue(dom.contains("Paired comparisons"));
    }
}
