package org.trajeval.figures;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Tick positions at 1, 2 or 5 times a power of ten, about {@code target} of them inside
 * [min, max], and their labels with as many decimals as the step needs (always a leading zero:
 * {@code 0.05}, never {@code .05}).
 */
final class Ticks {
    private Ticks() {
    }

    /** @return tick values inside [min, max] */
    static double[] of(double min, double max, int target) {
        double step = step(min, max, target);
        List<Double> v = new ArrayList<>();
        for (double k = Math.ceil(min / step - 1e-9); k * step <= max + 1e-9 * step; k++) {
            v.add(k * step == 0 ? 0.0 : k * step);
        }
        return v.stream().mapToDouble(Double::doubleValue).toArray();
    }

    /** @return the step between ticks */
    static double step(double min, double max, int target) {
        double raw = (max - min) / Math.max(1, target);
        double p = Math.pow(10, Math.floor(Math.log10(raw)));
        double f = raw / p;
        return (f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10) * p;
    }

    /** @return labels of the ticks, decimals from the step */
    static String[] labels(double[] ticks, double step) {
        int decimals = Math.max(0, (int) -Math.floor(Math.log10(step) + 1e-9));
        String[] out = new String[ticks.length];
        boolean big = false;
        for (double t : ticks) {
            big |= Math.abs(t) >= 1e6;
        }
        for (int i = 0; i < ticks.length; i++) {
            out[i] = big ? String.format(Locale.ROOT, "%.3g", ticks[i])
                    : String.format(Locale.ROOT, "%." + decimals + "f", ticks[i]);
        }
        return out;
    }
}
