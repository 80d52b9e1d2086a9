package org.trajeval.e2e;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Assumptions;

/**
 * Opens a page in Debian's headless Chromium as a reader would: the page's own console messages
 * (errors from the page itself; our pages have no script), and for every image whether it loaded
 * and whether it shows data (a figure with fewer than {@link #MIN_COLOURED} coloured pixels in a
 * thousand is blank: axes, text and grid are grey). A screenshot of the whole page is kept in
 * {@code build/screenshots/} (CI artefacts).
 */
final class HeadlessChromium {
    static final Path CHROMIUM = Path.of("/usr/bin/chromium");
    /** Coloured (saturated) pixels per thousand below which a figure counts as blank. */
    static final int MIN_COLOURED = 2;
    private static final Pattern PROBE = Pattern.compile("images=(\\d+) broken=(\\d+) blank=(\\d+) blankList=(.*?)<");

    /**
     * @param images images on the page
     * @param broken images that did not load
     * @param blank images without data drawn
     * @param blankAlts alt texts of the blank ones
     * @param console the page's console lines
     * @param screenshot the screenshot file
     */
    record Result(int images, int broken, int blank, String blankAlts, List<String> console, Path screenshot) {
    }

    private HeadlessChromium() {
    }

    static void assumeInstalled() {
        Assumptions.assumeTrue(Files.isExecutable(CHROMIUM),
                "SKIPPED LOUDLY: /usr/bin/chromium is absent; run scripts/ensure-tools (apt-get install chromium)");
    }

    static Result open(Path page, Path work, String screenshotName) throws IOException, InterruptedException {
        String html = Files.readString(page);
        // a copy beside the page with a probe that writes what the browser drew into the DOM
        String probe = "<script>window.addEventListener('load',function(){var imgs=document.images,bad=0,blank=0,"
                + "names=[];for(var i=0;i<imgs.length;i++){var im=imgs[i];if(!(im.complete&&im.naturalWidth>0)){"
                + "bad++;continue;}var c=document.createElement('canvas');c.width=im.naturalWidth;"
                + "c.height=im.naturalHeight;var g=c.getContext('2d');g.drawImage(im,0,0);"
                + "var d=g.getImageData(0,0,c.width,c.height).data,col=0;for(var k=0;k<d.length;k+=4){"
                + "var mx=Math.max(d[k],d[k+1],d[k+2]),mn=Math.min(d[k],d[k+1],d[k+2]);if(mx-mn>40)col++;}"
                + "if(col*1000<" + MIN_COLOURED + "*(d.length/4)){blank++;names.push(im.alt);}}"
                + "var p=document.createElement('pre');p.id='probe';p.textContent='images='+imgs.length+' broken='"
                + "+bad+' blank='+blank+' blankList='+names.join('|');document.body.appendChild(p);});</script></body>";
        Path probed = page.resolveSibling(".probe-" + page.getFileName());
        Files.writeString(probed, html.replace("</body>", probe));
        Path err = work.resolve("chromium-" + screenshotName + ".log");
        Process p = new ProcessBuilder(CHROMIUM.toString(), "--headless", "--no-sandbox", "--disable-gpu",
                "--enable-logging=stderr", "--v=0", "--user-data-dir=" + work.resolve("chromium-profile"),
                "--virtual-time-budget=10000", "--dump-dom", probed.toUri().toString())
                .redirectError(err.toFile()).start();
        String dom = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new AssertionError("chromium did not finish in 120 s");
        }
        Files.delete(probed);
        Matcher m = PROBE.matcher(dom);
        if (!m.find()) {
            throw new AssertionError("probe result missing from the DOM (did the page load?)");
        }
        List<String> console = Files.readAllLines(err).stream().filter(l -> l.contains(":CONSOLE")).toList();

        Path shots = Path.of(System.getProperty("trajeval.projectDir", ".")).resolve("build/screenshots");
        Files.createDirectories(shots);
        Path shot = shots.resolve(screenshotName + ".png");
        Process s = new ProcessBuilder(CHROMIUM.toString(), "--headless", "--no-sandbox", "--disable-gpu",
                "--hide-scrollbars", "--user-data-dir=" + work.resolve("chromium-profile"), "--window-size=1600,2400",
                "--virtual-time-budget=10000", "--screenshot=" + shot, page.toUri().toString())
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(ProcessBuilder.Redirect.DISCARD)
                .start();
        if (!s.waitFor(120, TimeUnit.SECONDS)) {
            s.destroyForcibly();
            throw new AssertionError("chromium screenshot did not finish in 120 s");
        }
        return new Result(Integer.parseInt(m.group(1)), Integer.parseInt(m.group(2)), Integer.parseInt(m.group(3)),
                m.group(4), console, shot);
    }
}
