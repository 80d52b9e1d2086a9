package org.trajeval.figures;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.io.ByteArrayInputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import javax.imageio.ImageIO;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.w3c.dom.Document;

/** The two renderers: SVG is well-formed XML with the figure's text, PNG decodes and is not blank. */
class FigureFilesTest {
    @TempDir
    Path dir;

    @Test
    void everyFigureIsWrittenAsSvgAndPngAndTheIndexLinksThem() throws Exception {
        List<Figure> figs = EvalPlotPage.write(EvalFiguresTest.kittiLikeDrive(300, "se3", true), PlotPlane.AUTO, dir,
                FigurePage.Progress.none());
        assertEquals(11, figs.size());
        String index = Files.readString(dir.resolve(EvalPlotPage.INDEX));
        for (Figure f : figs) {
            Document svg = DocumentBuilderFactory.newInstance().newDocumentBuilder()
                    .parse(dir.resolve(f.name() + ".svg").toFile());
            assertEquals("svg", svg.getDocumentElement().getNodeName());
            assertTrue(Files.readString(dir.resolve(f.name() + ".svg")).contains(SvgCanvas.escape(f.x().label())));
            BufferedImage png = ImageIO.read(new ByteArrayInputStream(Files.readAllBytes(dir.resolve(f.name()
                    + ".png"))));
            assertEquals(FigurePainter.WIDTH, png.getWidth());
            assertEquals(FigurePainter.HEIGHT, png.getHeight());
            assertTrue(index.contains("href=\"" + f.name() + ".svg\""), f.name());
        }
        assertTrue(!index.contains("http://") && !index.contains("https://"), "the page fetches nothing");
    }

    @Test
    void theTrajectoryPlotAreaIsNotBlank() throws Exception {
        Figure f = EvalFigures.of(EvalFiguresTest.kittiLikeDrive(300, "se3", false), PlotPlane.AUTO).get(0);
        BufferedImage png = ImageIO.read(new ByteArrayInputStream(FigureFiles.png(f, 1.0)));
        int coloured = 0;
        for (int y = 60; y < 380; y += 2) {
            for (int x = 90; x < 420; x += 2) {
                int rgb = png.getRGB(x, y) & 0xffffff;
                int r = rgb >> 16;
                int g = (rgb >> 8) & 255;
                int b = rgb & 255;
                if (Math.max(r, Math.max(g, b)) - Math.min(r, Math.min(g, b)) > 40) {
                    coloured++; // the viridis path, not grid grey or white
                }
            }
        }
        assertTrue(coloured > 50, "coloured pixels in the plot area: " + coloured);
    }
}
