package org.trajeval.figures;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** Points closer than half a pixel to the last drawn one are not drawn; ends and peaks are. */
class ThinningTest {
    @Test
    void aDenseStraightLineKeepsAboutTwoPointsPerPixelAndBothEnds() {
        // 20 000 points across 600 px: 0.03 px apart, so one point in about 17 (every 0.5 px) is kept
        int n = 20_000;
        double[] x = new double[n];
        double[] y = new double[n];
        for (int i = 0; i < n; i++) {
            x[i] = 600.0 * i / (n - 1);
            y[i] = 100;
        }
        int k = FigurePainter.thin(x, y, n);
        assertTrue(k <= 1202 && k >= 1100, "kept " + k);
        assertEquals(0.0, x[0]);
        assertEquals(600.0, x[k - 1]);
    }

    @Test
    void aOnePixelZigZagInOneColumnIsKept() {
        // min/max decimated series: peaks share a column but lie 1 px or more apart vertically
        double[] x = {10, 10, 10, 10, 10.2};
        double[] y = {0, 1, 0, 1, 0};
        assertEquals(5, FigurePainter.thin(x, y, 5));
    }
}
