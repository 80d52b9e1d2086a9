package org.trajeval.figures;

/**
 * Maps a value to a colour (viridis, perceptually uniform and readable in grey) over
 * [min, max]; drawn as a colour bar labelled with the value's name and unit.
 *
 * @param label label with unit, e.g. {@code "ATE (m)"}
 * @param min value at the dark end
 * @param max value at the bright end
 */
public record ColourScale(String label, double min, double max) {
    // viridis at 0, 0.125, ..., 1 (matplotlib's _viridis_data at those positions)
    private static final int[] STOPS = {0x440154, 0x472d7b, 0x3b528b, 0x2c728e, 0x21918c, 0x28ae80, 0x5ec962,
        0xaddc30, 0xfde725};

    /** @return the colour of v, clamped to the ends */
    public int rgb(double v) {
        double f = max > min ? (v - min) / (max - min) : 0.0;
        if (!(f >= 0)) {
            f = 0;
        }
        f = Math.min(1.0, f) * (STOPS.length - 1);
        int i = Math.min(STOPS.length - 2, (int) f);
        double w = f - i;
        int a = STOPS[i];
        int b = STOPS[i + 1];
        int r = (int) Math.round(((a >> 16) & 255) * (1 - w) + ((b >> 16) & 255) * w);
        int g = (int) Math.round(((a >> 8) & 255) * (1 - w) + ((b >> 8) & 255) * w);
        int bl = (int) Math.round((a & 255) * (1 - w) + (b & 255) * w);
        return (r << 16) | (g << 8) | bl;
    }
}
