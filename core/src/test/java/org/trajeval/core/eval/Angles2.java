package org.trajeval.core.eval;

/** Test helper: wraps by the lesson's formula (a + pi) mod 2 pi - pi, written independently. */
final class Angles2 {
    private Angles2() {
    }

    static double wrapForTest(double a) {
        double r = Math.IEEEremainder(a, 2 * Math.PI);
        return r >= Math.PI ? r - 2 * Math.PI : r;
    }
}
