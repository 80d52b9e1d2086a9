package org.trajeval.core.geom;

/**
 * Spherical linear interpolation between two quaternions q0 and q1 (w, x, y, z; any norm) as
 * transformations.py's {@code quaternion_slerp} (used by evo) computes it: a = q0 / |q0|,
 * b = q1 / |q1|; a at f = 0, b at f = 1, a when a and b are parallel (||a . b| - 1| or the arc
 * below 4 ulp(1)); otherwise, along the shorter arc,
 * <pre>
 *   q(f) = a sin((1 - f) theta) / sin theta + b' sin(f theta) / sin theta,
 *   cos theta = |a . b|,  b' = b, or -b when a . b &lt; 0.
 * </pre>
 * Example: a = (1, 0, 0, 0), b = (0, 0, 0, 1) (a half turn about z): theta = pi/2 and
 * q(1/2) = (cos pi/4, 0, 0, sin pi/4), a quarter turn.
 *
 * <p>Held as an object so that what depends only on the two ends (the normalisations, the dot
 * product, theta by {@link StrictAcos} and 1 / sin theta) is computed once for every fraction
 * asked on one segment ({@link #at}), and so that the next segment, which starts where this one
 * ends, keeps the normalised end ({@link #advance}). Each value is computed by the operations and
 * in the order of one {@link Rotations#slerp} call (which uses this class), so the bits are the same.
 */
public final class Slerp {
    /** transformations.py's _EPS * 4: ends closer than this to parallel give a. */
    private static final double EPS4 = 4.0 * Math.ulp(1.0);

    private double a0;
    private double a1;
    private double a2;
    private double a3;
    private double b0;
    private double b1;
    private double b2;
    private double b3;
    /** True once the arc of these ends is known ({@link #arc}). */
    private boolean arcKnown;
    /** True when the ends are parallel (every fraction strictly inside gives a). */
    private boolean parallel;
    private double theta;
    private double invSin;
    /** b', the end on the shorter arc side (b or -b). */
    private double c0;
    private double c1;
    private double c2;
    private double c3;

    /** Sets the two ends, q0 = (w0, x0, y0, z0) and q1 = (w1, x1, y1, z1). */
    public void ends(double w0, double x0, double y0, double z0, double w1, double x1, double y1, double z1) {
        double n0 = Math.sqrt(w0 * w0 + x0 * x0 + y0 * y0 + z0 * z0);
        a0 = w0 / n0;
        a1 = x0 / n0;
        a2 = y0 / n0;
        a3 = z0 / n0;
        end(w1, x1, y1, z1);
    }

    /** Moves to the segment from the current q1 to a new q1 = (w1, x1, y1, z1). */
    public void advance(double w1, double x1, double y1, double z1) {
        a0 = b0;
        a1 = b1;
        a2 = b2;
        a3 = b3;
        end(w1, x1, y1, z1);
    }

    /**
     * Sets this slerp to the segment that follows {@code previous}'s: from its normalised q1 to a new
     * q1 = (w1, x1, y1, z1), as {@link #advance} on {@code previous} would.
     */
    public void follow(Slerp previous, double w1, double x1, double y1, double z1) {
        a0 = previous.b0;
        a1 = previous.b1;
        a2 = previous.b2;
        a3 = previous.b3;
        end(w1, x1, y1, z1);
    }

    private void end(double w1, double x1, double y1, double z1) {
        double n1 = Math.sqrt(w1 * w1 + x1 * x1 + y1 * y1 + z1 * z1);
        b0 = w1 / n1;
        b1 = x1 / n1;
        b2 = y1 / n1;
        b3 = z1 / n1;
        arcKnown = false;
    }

    /** Writes q(f), f in [0, 1], into {@code out[o..o+4)} as (w, x, y, z). */
    public void at(double f, double[] out, int o) {
        if (f == 0.0) {
            put(out, o, a0, a1, a2, a3);
            return;
        }
        if (f == 1.0) {
            put(out, o, b0, b1, b2, b3);
            return;
        }
        if (!arcKnown) {
            arc();
        }
        if (parallel) {
            put(out, o, a0, a1, a2, a3);
            return;
        }
        double s0 = Math.sin((1.0 - f) * theta) * invSin;
        double s1 = Math.sin(f * theta) * invSin;
        put(out, o, a0 * s0 + c0 * s1, a1 * s0 + c1 * s1, a2 * s0 + c2 * s1, a3 * s0 + c3 * s1);
    }

    /**
     * {@code x.at(fx, outX, ox)} and then {@code y.at(fy, outY, oy)} (x and y may be the same
     * slerp), with the steps of the two long chains (arc cosine, sines, division) taken side by side
     * when both fractions are strictly inside their segments, so the processor overlaps them. The
     * same operations on each value, hence the same bits as the two calls.
     */
    public static void atBoth(Slerp x, double fx, double[] outX, int ox, Slerp y, double fy, double[] outY, int oy) {
        if (fx == 0.0 || fx == 1.0 || fy == 0.0 || fy == 1.0) {
            x.at(fx, outX, ox);
            y.at(fy, outY, oy);
            return;
        }
        if (x != y && !x.arcKnown && !y.arcKnown) {
            arcs(x, y);
        } else {
            if (!x.arcKnown) {
                x.arc();
            }
            if (!y.arcKnown) {
                y.arc();
            }
        }
        if (x.parallel || y.parallel) {
            x.at(fx, outX, ox);
            y.at(fy, outY, oy);
            return;
        }
        double xs0 = Math.sin((1.0 - fx) * x.theta) * x.invSin;
        double ys0 = Math.sin((1.0 - fy) * y.theta) * y.invSin;
        double xs1 = Math.sin(fx * x.theta) * x.invSin;
        double ys1 = Math.sin(fy * y.theta) * y.invSin;
        put(outX, ox, x.a0 * xs0 + x.c0 * xs1, x.a1 * xs0 + x.c1 * xs1, x.a2 * xs0 + x.c2 * xs1,
                x.a3 * xs0 + x.c3 * xs1);
        put(outY, oy, y.a0 * ys0 + y.c0 * ys1, y.a1 * ys0 + y.c1 * ys1, y.a2 * ys0 + y.c2 * ys1,
                y.a3 * ys0 + y.c3 * ys1);
    }

    /** {@link #arc} of two slerps, side by side; either one alone when the other's ends are parallel. */
    private static void arcs(Slerp x, Slerp y) {
        double dx = x.a0 * x.b0 + x.a1 * x.b1 + x.a2 * x.b2 + x.a3 * x.b3;
        double dy = y.a0 * y.b0 + y.a1 * y.b1 + y.a2 * y.b2 + y.a3 * y.b3;
        if (Math.abs(Math.abs(dx) - 1.0) < EPS4 || Math.abs(Math.abs(dy) - 1.0) < EPS4) {
            x.arc();
            y.arc();
            return;
        }
        x.arcKnown = true;
        y.arcKnown = true;
        x.parallel = false;
        y.parallel = false;
        dx = x.shorterArc(dx);
        dy = y.shorterArc(dy);
        double tx = StrictAcos.acos(dx);
        double ty = StrictAcos.acos(dy);
        x.theta = tx;
        y.theta = ty;
        x.parallel = Math.abs(tx) < EPS4;
        y.parallel = Math.abs(ty) < EPS4;
        if (!x.parallel && !y.parallel) {
            double sx = Math.sin(tx);
            double sy = Math.sin(ty);
            x.invSin = 1.0 / sx;
            y.invSin = 1.0 / sy;
        } else {
            if (!x.parallel) {
                x.invSin = 1.0 / Math.sin(tx);
            }
            if (!y.parallel) {
                y.invSin = 1.0 / Math.sin(ty);
            }
        }
    }

    /** Sets b' (b, or -b when d = a . b &lt; 0) and returns |d|: the steps of {@link #arc} after its test. */
    private double shorterArc(double d) {
        if (d < 0.0) {
            c0 = -b0;
            c1 = -b1;
            c2 = -b2;
            c3 = -b3;
            return -d;
        }
        c0 = b0;
        c1 = b1;
        c2 = b2;
        c3 = b3;
        return d;
    }

    /** The parts of q(f) that depend on the ends only: b', theta and 1 / sin theta. */
    private void arc() {
        arcKnown = true;
        double d = a0 * b0 + a1 * b1 + a2 * b2 + a3 * b3;
        parallel = Math.abs(Math.abs(d) - 1.0) < EPS4;
        if (parallel) {
            return;
        }
        d = shorterArc(d);
        theta = StrictAcos.acos(d); // Math.acos's bits, without its slow software square root
        parallel = Math.abs(theta) < EPS4;
        if (!parallel) {
            invSin = 1.0 / Math.sin(theta);
        }
    }

    private static void put(double[] out, int o, double w, double x, double y, double z) {
        out[o] = w;
        out[o + 1] = x;
        out[o + 2] = y;
        out[o + 3] = z;
    }
}
