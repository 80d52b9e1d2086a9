package org.trajeval.figures;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.awt.image.BufferedImage;
import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.zip.Inflater;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The hand-written PDF backend: a valid PDF 1.4 file whose page poppler draws. */
class PdfCanvasTest {
    @TempDir
    Path dir;

    private static String latin1(byte[] b) {
        return new String(b, StandardCharsets.ISO_8859_1);
    }

    /** @return the page's content stream, inflated */
    private static String content(byte[] pdf) throws Exception {
        String text = latin1(pdf);
        int start = text.indexOf("stream\n") + "stream\n".length();
        Matcher m = Pattern.compile("/Length (\\d+) /Filter /FlateDecode").matcher(text);
        assertTrue(m.find());
        Inflater inf = new Inflater();
        inf.setInput(pdf, start, Integer.parseInt(m.group(1)));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        byte[] buf = new byte[4096];
        while (!inf.finished()) {
            out.write(buf, 0, inf.inflate(buf));
        }
        return latin1(out.toByteArray());
    }

    @Test
    void crossReferenceTablePointsAtEveryObjectAndTheTrailerAtTheTable() {
        byte[] pdf = FigureFiles.pdf(EvalFigures.of(EvalFiguresTest.kittiLikeDrive(300, "se3", true), PlotPlane.AUTO)
                .get(0));
        String t = latin1(pdf);
        assertTrue(t.startsWith("%PDF-1.4\n"));
        assertTrue(t.endsWith("%%EOF\n"));
        int xref = Integer.parseInt(t.replaceAll("(?s).*startxref\n(\\d+)\n%%EOF\n$", "$1"));
        assertTrue(t.startsWith("xref\n0 8\n", xref), t.substring(xref, Math.min(t.length(), xref + 20)));
        String[] rows = t.substring(xref).split("\n");
        for (int k = 1; k <= 7; k++) {
            int offset = Integer.parseInt(rows[2 + k].substring(0, 10));
            assertTrue(t.startsWith(k + " 0 obj\n", offset), "object " + k);
        }
        assertTrue(t.contains("/BaseFont /Helvetica "));
        assertTrue(t.contains("/MediaBox [0 0 760 440]"));
    }

    @Test
    void centredTextIsShiftedByHalfItsHelveticaWidthAndEscaped() throws Exception {
        PdfCanvas c = new PdfCanvas(760, 440);
        // Helvetica (Adobe AFM): H 722 + i 222 = 944 / 1000 em; at 10 pt, 9.44 pt wide, so centred on
        // x = 100 it starts at 100 - 4.72 = 95.28
        c.text(100, 50, "Hi", 10, Canvas.Anchor.MIDDLE, false, false);
        // '(' and ')' escaped, the plus-minus sign as WinAnsi octal 261; right-aligned bold at x = 300:
        // a 556 + ( 333 + b 611 + ) 333 + plus-minus 584 = 2417 / 1000 em, at 10 pt 24.17 pt
        c.text(300, 60, "a(b)\u00b1", 10, Canvas.Anchor.END, false, true);
        c.text(20, 200, "y (m)", 12, Canvas.Anchor.START, true, false);
        String s = content(c.finish());
        assertTrue(s.contains("BT /F1 10 Tf 1 0 0 -1 95.28 50 Tm (Hi) Tj ET"), s);
        assertTrue(s.contains("BT /F2 10 Tf 1 0 0 -1 275.83 60 Tm (a\\(b\\)\\261) Tj ET"), s);
        assertTrue(s.contains("BT /F1 12 Tf 0 -1 -1 0 20 200 Tm (y \\(m\\)) Tj ET"), s); // reads upwards
        assertTrue(s.startsWith("1 0 0 -1 0 440 cm\n"), s); // y flipped once: canvas pixels are points
        assertArrayEquals(new byte[] {'a', (byte) 0x85}, PdfCanvas.winAnsi("a\u2026"));
    }

    @Test
    void translucentFillsUseOneGraphicsStatePerOpacity() throws Exception {
        PdfCanvas c = new PdfCanvas(100, 100);
        c.rect(0, 0, 10, 10, 0xff0000, 0.2, -1);
        c.rect(20, 0, 10, 10, 0x00ff00, 0.2, -1);
        c.polygon(new double[] {0, 10, 5}, new double[] {0, 0, 10}, 3, 0x0000ff, 0.5);
        byte[] pdf = c.finish();
        assertTrue(latin1(pdf).contains("/ExtGState << /A0 << /Type /ExtGState /ca 0.2 >> /A1 << /Type /ExtGState "
                + "/ca 0.5 >> >>"), latin1(pdf));
        assertEquals(2, content(pdf).split("/A0 gs", -1).length - 1);
    }

    @Test
    void popplerDrawsThePageWithItsColours() throws Exception {
        Path pdf = dir.resolve("trajectories.pdf");
        Files.write(pdf, FigureFiles.pdf(EvalFigures.of(EvalFiguresTest.kittiLikeDrive(300, "se3", true),
                PlotPlane.AUTO).get(0)));
        String info = run("pdfinfo", pdf.toString());
        assertTrue(info.contains("Page size:       760 x 440 pts"), info);
        assertTrue(info.contains("PDF version:     1.4"), info);
        run("pdftoppm", "-png", "-r", "72", "-singlefile", pdf.toString(), dir.resolve("page").toString());
        BufferedImage img = ImageIO.read(dir.resolve("page.png").toFile());
        assertEquals(760, img.getWidth());
        assertEquals(440, img.getHeight());
        int coloured = 0;
        for (int y = 0; y < img.getHeight(); y++) {
            for (int x = 0; x < img.getWidth(); x++) {
                int p = img.getRGB(x, y);
                int r = (p >> 16) & 255;
                int g = (p >> 8) & 255;
                int b = p & 255;
                if (Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b)) > 60) {
                    coloured++; // viridis path and colour bar, not grey text or grid
                }
            }
        }
        assertTrue(coloured > 2000, "coloured pixels " + coloured);
    }

    private static String run(String... command) throws Exception {
        Process p;
        try {
            p = new ProcessBuilder(command).redirectErrorStream(true).start();
        } catch (java.io.IOException e) {
            return fail(command[0] + " (Debian's poppler-utils) is missing: run scripts/ensure-tools");
        }
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(0, p.exitValue(), out);
        return out;
    }
}
