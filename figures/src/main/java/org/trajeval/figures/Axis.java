package org.trajeval.figures;

import java.util.List;
import java.util.Objects;

/**
 * One axis of a figure: its label (with the unit, e.g. {@code "time (s)"}) and its range.
 * Ranges are chosen here, not by the renderer, so tests read them: error axes start at zero, and a
 * span narrower than the data's resolution is widened rather than magnified (two values that agree
 * to 8 digits are drawn as equal, not as the whole height of the plot).
 *
 * @param label label with unit in parentheses
 * @param min lower end (in the label's unit)
 * @param max upper end, greater than min
 * @param categories tick labels at 1, 2, ... for a categorical axis (box plots), else empty
 */
public record Axis(String label, double min, double max, List<String> categories) {
    /** Smallest relative span drawn: 1e-6 of the values' magnitude (doubles from text carry about 1e-8). */
    static final double RESOLUTION = 1e-6;

    /** @throws IllegalArgumentException on an empty or non-finite range */
    public Axis {
        Objects.requireNonNull(label, "label");
        categories = List.copyOf(categories);
        if (!(Double.isFinite(min) && Double.isFinite(max) && max > min)) {
            throw new IllegalArgumentException("axis '" + label + "' needs finite min < max, found [" + min + ", "
                    + max + "]");
        }
    }

    /** An axis from 0 to 5 % above the largest finite value (errors, counts). */
    public static Axis fromZero(String label, double[]... values) {
        double hi = 0;
        for (double[] v : values) {
            for (double d : v) {
                if (Double.isFinite(d)) {
                    hi = Math.max(hi, d);
                }
            }
        }
        return new Axis(label, 0, hi > 0 ? hi * 1.05 : 1.0, List.of());
    }

    /**
     * An axis over the finite values with 5 % padding on each side; a span below
     * {@link #RESOLUTION} of the magnitude is widened to it, centred on the data.
     */
    public static Axis spanning(String label, double[]... values) {
        double lo = Double.POSITIVE_INFINITY;
        double hi = Double.NEGATIVE_INFINITY;
        for (double[] v : values) {
            for (double d : v) {
                if (Double.isFinite(d)) {
                    lo = Math.min(lo, d);
                    hi = Math.max(hi, d);
                }
            }
        }
        if (lo > hi) {
            return new Axis(label, 0, 1, List.of());
        }
        double floor = Math.max(RESOLUTION * Math.max(Math.abs(lo), Math.abs(hi)), 1e-12);
        double span = Math.max(hi - lo, floor);
        double mid = 0.5 * (lo + hi);
        return new Axis(label, mid - 0.55 * span, mid + 0.55 * span, List.of());
    }

    /** A categorical axis with the given names at positions 1..n. */
    public static Axis categorical(String label, List<String> names) {
        return new Axis(label, 0.5, names.size() + 0.5, names);
    }

    /** @return the same axis with another range */
    public Axis withRange(double newMin, double newMax) {
        return new Axis(label, newMin, newMax, categories);
    }
}
