package org.trajeval.core.geom;

/** Angle helpers (rad). */
public final class Angles {
    private Angles() {
    }

    /**
     * Wraps an angle into [-pi, pi): wrap(a) = a - 2 pi floor((a + pi) / (2 pi)), the lesson's
     * {@code (a + pi) mod 2 pi - pi}. Example: wrap(3 pi / 2) = -pi / 2.
     *
     * @param a angle (rad)
     * @return the equivalent angle in [-pi, pi) (rad)
     */
    public static double wrap(double a) {
        if (a >= -Math.PI && a < Math.PI) {
            return a;
        }
        double twoPi = 2.0 * Math.PI;
        double r = (a + Math.PI) % twoPi;
        if (r < 0) {
            r += twoPi;
        }
        return r - Math.PI;
    }
}
