package org.trajeval.core.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

/**
 * A {@link Slerp} kept across fractions and segments must give, bit for bit, what one
 * transformations.py {@code quaternion_slerp} call gives for each (ends, fraction): the reference
 * here is that function written out in one piece ({@link #quaternionSlerp}, the body
 * {@link Rotations#slerp} had before it used this class).
 */
class SlerpTest {
    /** transformations.py's _EPS * 4. */
    private static final double EPS4 = 4.0 * Math.ulp(1.0);

    @Test
    void halfOfAHalfTurnAboutZIsAQuarterTurn() {
        // a = identity, b = half turn about z: theta = pi/2, q(1/2) = (cos pi/4, 0, 0, sin pi/4) by hand
        Slerp s = new Slerp();
        s.ends(1, 0, 0, 0, 0, 0, 0, 1);
        double[] q = new double[4];
        s.at(0.5, q, 0);
        assertEquals(Math.cos(Math.PI / 4), q[0], 1e-15);
        assertEquals(0.0, q[1], 0.0);
        assertEquals(0.0, q[2], 0.0);
        assertEquals(Math.sin(Math.PI / 4), q[3], 1e-15);
    }

    @Test
    void manyFractionsOnOneSegmentEqualOneCallEachBitForBit() {
        Random rnd = new Random(71);
        Slerp s = new Slerp();
        double[] got = new double[4];
        double[] want = new double[4];
        for (int seg = 0; seg < 2000; seg++) {
            double[] q0 = randomQuaternion(rnd);
            double[] q1 = seg % 7 == 0 ? scaled(q0, -1.5) : seg % 11 == 0 ? scaled(q0, 0.5) : randomQuaternion(rnd);
            s.ends(q0[0], q0[1], q0[2], q0[3], q1[0], q1[1], q1[2], q1[3]);
            for (int i = 0; i < 12; i++) {
                double f = i == 0 ? 0.0 : i == 1 ? 1.0 : rnd.nextDouble();
                s.at(f, got, 0);
                quaternionSlerp(q0, q1, f, want);
                assertBitsEqual(want, got, "segment " + seg + ", f = " + f);
            }
        }
    }

    @Test
    void advancingAlongAChainOfQuaternionsEqualsSettingBothEndsBitForBit() {
        Random rnd = new Random(72);
        double[][] chain = new double[3000][];
        for (int i = 0; i < chain.length; i++) {
            // a smooth chain with sign flips (the shorter-arc case) and repeats (parallel ends)
            chain[i] = i == 0 ? randomQuaternion(rnd) : i % 13 == 0 ? scaled(chain[i - 1], -1.0)
                    : i % 17 == 0 ? chain[i - 1].clone() : nudged(chain[i - 1], rnd);
        }
        Slerp s = new Slerp();
        s.ends(chain[0][0], chain[0][1], chain[0][2], chain[0][3], chain[1][0], chain[1][1], chain[1][2],
                chain[1][3]);
        double[] got = new double[4];
        double[] want = new double[4];
        for (int i = 1; i < chain.length; i++) {
            if (i > 1) {
                s.advance(chain[i][0], chain[i][1], chain[i][2], chain[i][3]);
            }
            for (int k = 0; k < 3; k++) {
                double f = k == 2 && i % 5 == 0 ? 1.0 : rnd.nextDouble();
                s.at(f, got, 0);
                quaternionSlerp(chain[i - 1], chain[i], f, want);
                assertBitsEqual(want, got, "segment " + i + ", f = " + f);
            }
        }
    }

    @Test
    void twoSlerpsSideBySideEqualOneCallEachBitForBit() {
        // atBoth on two segments (following, unrelated, the same slerp twice) against one call each,
        // with parallel, antipodal and half-turn ends and the fractions 0 and 1 on either side
        Random rnd = new Random(74);
        Slerp x = new Slerp();
        Slerp y = new Slerp();
        double[] gotX = new double[4];
        double[] gotY = new double[6];
        double[] want = new double[4];
        for (int i = 0; i < 20000; i++) {
            double[] q0 = randomQuaternion(rnd);
            double[] q1 = awkwardNeighbour(q0, i, rnd);
            double[] q2 = awkwardNeighbour(q1, i / 9, rnd);
            x.ends(q0[0], q0[1], q0[2], q0[3], q1[0], q1[1], q1[2], q1[3]);
            int shape = i % 3;
            double[] y0 = shape == 0 ? q1 : shape == 1 ? randomQuaternion(rnd) : q0;
            double[] y1 = shape == 2 ? q1 : q2;
            if (shape == 0) {
                y.follow(x, q2[0], q2[1], q2[2], q2[3]);
            } else if (shape == 1) {
                y.ends(y0[0], y0[1], y0[2], y0[3], y1[0], y1[1], y1[2], y1[3]);
            }
            Slerp second = shape == 2 ? x : y;
            if (i % 10 == 9) {
                x.at(0.5, gotX, 0); // the arc of x already known
            }
            double fx = i % 23 == 0 ? 0.0 : i % 29 == 0 ? 1.0 : rnd.nextDouble();
            double fy = i % 31 == 0 ? 0.0 : i % 37 == 0 ? 1.0 : rnd.nextDouble();
            Slerp.atBoth(x, fx, gotX, 0, second, fy, gotY, 2);
            quaternionSlerp(q0, q1, fx, want);
            assertBitsEqual(want, gotX, "first, case " + i + ", f = " + fx);
            quaternionSlerp(y0, y1, fy, want);
            assertBitsEqual(want, new double[] {gotY[2], gotY[3], gotY[4], gotY[5]}, "second, case " + i + ", f = " + fy);
        }
    }

    /** q itself, -q, q nudged by about 1e-9, q turned by a half turn or a half turn less 1e-7 rad, or a random one. */
    private static double[] awkwardNeighbour(double[] q, int i, Random rnd) {
        switch (i % 7) {
            case 0:
                return q.clone();
            case 1:
                return scaled(q, -1.0);
            case 2:
                return new double[] {q[0] + 1e-9, q[1] - 1e-9, q[2], q[3]};
            case 3:
                return new double[] {-q[1], q[0], -q[3], q[2]}; // q times (0, 1, 0, 0): a half turn, a . b = 0
            case 4: {
                double c = Math.cos((Math.PI - 1e-7) / 2);
                double s = Math.sin((Math.PI - 1e-7) / 2);
                return new double[] {c * q[0] - s * q[3], c * q[1] + s * q[2], c * q[2] - s * q[1], c * q[3] + s * q[0]};
            }
            default:
                return i % 2 == 0 ? nudged(q, rnd) : randomQuaternion(rnd);
        }
    }

    @Test
    void rotationsSlerpIsOneSlerpCall() {
        Random rnd = new Random(73);
        double[] got = new double[5];
        double[] want = new double[4];
        for (int i = 0; i < 1000; i++) {
            double[] q0 = randomQuaternion(rnd);
            double[] q1 = randomQuaternion(rnd);
            double f = rnd.nextDouble();
            Rotations.slerp(q0, q1, f, got, 1);
            quaternionSlerp(q0, q1, f, want);
            for (int c = 0; c < 4; c++) {
                assertEquals(Double.doubleToRawLongBits(want[c]), Double.doubleToRawLongBits(got[1 + c]));
            }
        }
    }

    /** transformations.py's quaternion_slerp(q0, q1, f, shortestpath=True), in one piece. */
    private static void quaternionSlerp(double[] q0, double[] q1, double f, double[] out) {
        double n0 = Math.sqrt(q0[0] * q0[0] + q0[1] * q0[1] + q0[2] * q0[2] + q0[3] * q0[3]);
        double n1 = Math.sqrt(q1[0] * q1[0] + q1[1] * q1[1] + q1[2] * q1[2] + q1[3] * q1[3]);
        double[] a = {q0[0] / n0, q0[1] / n0, q0[2] / n0, q0[3] / n0};
        double[] b = {q1[0] / n1, q1[1] / n1, q1[2] / n1, q1[3] / n1};
        if (f == 0.0) {
            System.arraycopy(a, 0, out, 0, 4);
            return;
        }
        if (f == 1.0) {
            System.arraycopy(b, 0, out, 0, 4);
            return;
        }
        double d = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
        if (Math.abs(Math.abs(d) - 1.0) < EPS4) {
            System.arraycopy(a, 0, out, 0, 4);
            return;
        }
        if (d < 0.0) {
            d = -d;
            for (int c = 0; c < 4; c++) {
                b[c] = -b[c];
            }
        }
        double angle = Math.acos(d);
        if (Math.abs(angle) < EPS4) {
            System.arraycopy(a, 0, out, 0, 4);
            return;
        }
        double isin = 1.0 / Math.sin(angle);
        double s0 = Math.sin((1.0 - f) * angle) * isin;
        double s1 = Math.sin(f * angle) * isin;
        for (int c = 0; c < 4; c++) {
            out[c] = a[c] * s0 + b[c] * s1;
        }
    }

    private static double[] randomQuaternion(Random rnd) {
        return new double[] {rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian(), rnd.nextGaussian()};
    }

    private static double[] scaled(double[] q, double s) {
        return new double[] {s * q[0], s * q[1], s * q[2], s * q[3]};
    }

    private static double[] nudged(double[] q, Random rnd) {
        return new double[] {q[0] + 0.01 * rnd.nextGaussian(), q[1] + 0.01 * rnd.nextGaussian(),
            q[2] + 0.01 * rnd.nextGaussian(), q[3] + 0.01 * rnd.nextGaussian()};
    }

    private static void assertBitsEqual(double[] want, double[] got, String what) {
        for (int c = 0; c < 4; c++) {
            assertEquals(Double.doubleToRawLongBits(want[c]), Double.doubleToRawLongBits(got[c]), what + ", part " + c);
        }
    }
}
