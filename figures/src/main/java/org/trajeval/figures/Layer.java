package org.trajeval.figures;

import java.util.List;

/**
 * What a figure draws, in data coordinates (the units of its axes). The renderer turns layers
 * into pixels; tests read the layers. Colours are 0xRRGGBB.
 */
public sealed interface Layer {

    /** @return the legend entry, or null for none */
    String label();

    /** A polyline. */
    record Line(String label, double[] x, double[] y, int rgb, float width, boolean dashed) implements Layer {
        /** @throws IllegalArgumentException when x and y differ in length */
        public Line {
            if (x.length != y.length) {
                throw new IllegalArgumentException("line '" + label + "': " + x.length + " x, " + y.length + " y");
            }
        }
    }

    /** A polyline coloured point by point from {@code value} through the figure's colour scale. */
    record Gradient(String label, double[] x, double[] y, double[] value) implements Layer {
        /** @throws IllegalArgumentException when the arrays differ in length */
        public Gradient {
            if (x.length != y.length || x.length != value.length) {
                throw new IllegalArgumentException("gradient '" + label + "': arrays differ in length");
            }
        }
    }

    /** A horizontal line across the plot at {@code y} (mean, median, RMSE). */
    record Rule(String label, double y, int rgb, boolean dashed) implements Layer {
    }

    /** A shaded horizontal band between {@code lower} and {@code upper} (mean +- std). */
    record Band(String label, double lower, double upper, int rgb) implements Layer {
    }

    /** A shaded area between two curves over the same x (the envelope of several seeds). */
    record Area(String label, double[] x, double[] lower, double[] upper, int rgb) implements Layer {
        /** @throws IllegalArgumentException when the arrays differ in length */
        public Area {
            if (x.length != lower.length || x.length != upper.length) {
                throw new IllegalArgumentException("area '" + label + "': arrays differ in length");
            }
        }
    }

    /** Markers (start and end of a path). */
    record Points(String label, double[] x, double[] y, int rgb, Shape shape) implements Layer {
    }

    /** Marker shapes. */
    enum Shape { CIRCLE, SQUARE }

    /** Histogram bars: bin i spans [edges[i], edges[i+1]) with height counts[i]. */
    record Bars(String label, double[] edges, double[] counts, int rgb) implements Layer {
        /** @throws IllegalArgumentException unless there is one more edge than counts */
        public Bars {
            if (edges.length != counts.length + 1) {
                throw new IllegalArgumentException("bars '" + label + "': need counts + 1 edges");
            }
        }
    }

    /**
     * Box plots (Tukey: box Q1..Q3, whiskers to the last value within 1.5 IQR), box i at x = at[i]
     * (categorical positions 1..n, or beside them for groups), halfWidth wide on each side.
     */
    record Boxes(String label, List<Box> boxes, double[] at, double halfWidth) implements Layer {
        /** @throws IllegalArgumentException when positions and boxes differ in number */
        public Boxes {
            boxes = List.copyOf(boxes);
            if (at.length != boxes.size() || !(halfWidth > 0)) {
                throw new IllegalArgumentException("boxes '" + label + "': " + boxes.size() + " boxes, " + at.length
                        + " positions, half width " + halfWidth);
            }
        }

        /** Boxes at the categorical positions 1..n, 0.25 wide on each side. */
        public Boxes(String label, List<Box> boxes) {
            this(label, boxes, java.util.stream.IntStream.rangeClosed(1, boxes.size()).asDoubleStream().toArray(),
                    0.25);
        }
    }

    /**
     * @param q1 first quartile, likewise median and q3
     * @param low lower whisker end
     * @param high upper whisker end
     * @param n number of values
     * @param rgb colour
     */
    record Box(double low, double q1, double median, double q3, double high, int n, int rgb) {
    }
}
