package org.trajeval.figures;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.util.List;
import javax.xml.parsers.DocumentBuilderFactory;
import org.junit.jupiter.api.Test;
import org.trajeval.core.report.SuiteReport;
import org.trajeval.core.report.SuiteReport.RankedMethod;
import org.trajeval.core.report.SuiteReport.Ranking;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.NodeList;

/** The diagram draws exactly the ranking's data: one hanging line per method at its rank, one bar per group. */
class RankDiagramSvgTest {
    private static Ranking ranking(List<List<String>> groups, Double... ranks) {
        List<String> names = List.of("alpha", "beta", "gamma", "de<l>ta");
        List<RankedMethod> m = new java.util.ArrayList<>();
        for (int i = 0; i < ranks.length; i++) {
            m.add(new RankedMethod(names.get(i), ranks[i]));
        }
        SuiteReport.RankTest t = new SuiteReport.RankTest(9.3, ranks.length - 1, null, 0.025);
        return new Ranking("ate_trans_rmse_m", "lower", 8, m, t, t, "pairwise Wilcoxon signed-rank tests on "
                + "ate_trans_rmse_m (6 tests), Holm", 0.05, groups);
    }

    private static Document parse(String svg) throws Exception {
        return DocumentBuilderFactory.newInstance().newDocumentBuilder()
                .parse(new ByteArrayInputStream(svg.getBytes(StandardCharsets.UTF_8)));
    }

    @Test
    void methodsHangAtTheirAverageRankAndGroupsBecomeBars() throws Exception {
        Ranking r = ranking(List.of(List.of("alpha", "gamma"), List.of("gamma", "beta", "de<l>ta")), 1.25, 3.0,
                2.5, 3.25);
        Document d = parse(RankDiagramSvg.render(r));
        NodeList lines = d.getElementsByTagName("polyline");
        assertEquals(4, lines.getLength());
        // methods in rank order alpha 1.25, gamma 2.5, beta 3.0, delta 3.25; axis from x(1) = 150 to x(4) = 490
        double[] expectedX = {RankDiagramSvg.x(1.25, 4), RankDiagramSvg.x(2.5, 4), RankDiagramSvg.x(3.0, 4),
            RankDiagramSvg.x(3.25, 4)};
        assertEquals(150.0, RankDiagramSvg.x(1, 4), 0.0);
        assertEquals(490.0, RankDiagramSvg.x(4, 4), 0.0);
        for (int i = 0; i < 4; i++) {
            String first = ((Element) lines.item(i)).getAttribute("points").split(" ")[0];
            assertEquals(expectedX[i], Double.parseDouble(first.split(",")[0]), 0.05, "method " + i);
        }
        int bars = 0;
        NodeList all = d.getElementsByTagName("line");
        for (int i = 0; i < all.getLength(); i++) {
            if ("group".equals(((Element) all.item(i)).getAttribute("class"))) {
                bars++;
            }
        }
        assertEquals(2, bars);
        String text = d.getDocumentElement().getTextContent();
        assertTrue(text.contains("alpha (1.25)") && text.contains("de<l>ta (3.25)"), text); // escaped, read back
    }

    @Test
    void aRankingWithoutRanksIsNotDrawn() {
        Ranking none = ranking(List.of(), null, null, null);
        assertTrue(!RankDiagramSvg.drawable(none));
        assertThrows(IllegalArgumentException.class, () -> RankDiagramSvg.render(none));
    }
}
