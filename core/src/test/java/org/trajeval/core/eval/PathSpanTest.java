package org.trajeval.core.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;
import org.junit.jupiter.api.Test;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * {@link PathSpan}, each hop computed once, must give every path length of the two running sums it
 * replaced ({@link PathSpanAsItWas}) bit for bit ({@link Double#doubleToRawLongBits}): seeded
 * random walks whose hops span twelve orders of magnitude (so that a sum taken in another order
 * would round differently), the pair sequences of every rule (every start pose in seconds and in
 * frames, strides, consecutive pairs), pairs longer than the ring of sums, start poses that jump
 * past the last end pose, and chunks that start inside the trajectory.
 */
class PathSpanTest {
    private static final int N = 12_000;

    @Test
    void everyPathLengthIsTheTwoRunningSumsBitForBit() {
        Random rnd = new Random(1515);
        AssociatedColumns poses = randomWalk(rnd, N);
        int sequences = 0;
        for (int start : new int[] {0, 1, 777, N / 2}) {
            // every start pose, in seconds: the first j with t_j >= t_i + delta (stamps 1 apart: j = i + delta)
            for (int d : new int[] {0, 1, 2, 5, 100, PathSpan.RING - 1, PathSpan.RING, PathSpan.RING + 1, 5000}) {
                sequences += same(poses, start, (k, ij) -> {
                    ij[0] = start + k;
                    ij[1] = start + k + d;
                });
            }
            // strides: (p d, p d + d); consecutive pairs of the walk are d = the gap between them
            for (int d : new int[] {1, 7, 1100, PathSpan.RING + 3}) {
                sequences += same(poses, start, (k, ij) -> {
                    ij[0] = start + k * d;
                    ij[1] = start + k * d + d;
                });
            }
        }
        // random non-decreasing i and j (i <= j), with i jumping past the last j and long pairs
        for (int run = 0; run < 40; run++) {
            int start = rnd.nextInt(100);
            int[] last = {start, start};
            long seed = rnd.nextLong();
            Random steps = new Random(seed);
            sequences += same(poses, start, (k, ij) -> {
                int i = last[0] + (steps.nextInt(8) == 0 ? steps.nextInt(3000) : steps.nextInt(2));
                int j = Math.max(last[1], i) + (steps.nextInt(10) == 0 ? steps.nextInt(2 * PathSpan.RING)
                        : steps.nextInt(3));
                ij[0] = i;
                ij[1] = j;
                last[0] = i;
                last[1] = j;
            });
        }
        assertEquals(4 * 13 + 40, sequences);
    }

    @Test
    void theLengthOfAPathIsTheSumOfItsHops() {
        // poses (0, 0), (3, 0), (3, 0), (6, 4) by hand: hops 3, 0 and sqrt(3^2 + 4^2) = 5 (m)
        double[] x = {0, 3, 3, 6};
        double[] y = {0, 0, 0, 4};
        AssociatedColumns poses = columns(x, y, new double[4]);
        PathSpan path = new PathSpan(poses, 0);
        assertEquals(0.0, path.between(0, 0), 0.0);
        assertEquals(3.0, path.between(0, 1), 0.0);
        assertEquals(3.0, path.between(0, 2), 0.0); // 3 + 0
        assertEquals(5.0, path.between(1, 3), 0.0); // 0 + 5
        assertEquals(5.0, path.between(2, 3), 0.0);
        assertEquals(0.0, path.between(3, 3), 0.0);
    }

    /** Fills {i, j} of pair k. */
    private interface Pairs {
        void pair(int k, int[] ij);
    }

    /** Compares both spans over the pairs while j stays on the trajectory; @return 1 */
    private static int same(AssociatedColumns poses, int start, Pairs pairs) {
        PathSpan now = new PathSpan(poses, start);
        PathSpanAsItWas was = new PathSpanAsItWas(poses, start);
        int[] ij = new int[2];
        int compared = 0;
        for (int k = 0;; k++) {
            pairs.pair(k, ij);
            if (ij[1] >= poses.size()) {
                break;
            }
            double expected = was.between(ij[0], ij[1]);
            double actual = now.between(ij[0], ij[1]);
            if (Double.doubleToRawLongBits(expected) != Double.doubleToRawLongBits(actual)) {
                assertEquals(expected, actual, 0.0, "pair " + k + " (" + ij[0] + ", " + ij[1] + ") from " + start);
                assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual),
                        "pair " + k + " (" + ij[0] + ", " + ij[1] + ") from " + start + ": sign of zero");
            }
            compared++;
        }
        assertTrue(compared > 0, "no pair compared from " + start);
        return 1;
    }

    /** A walk whose steps are 10^-6 .. 10^6 m long, in random directions. */
    private static AssociatedColumns randomWalk(Random rnd, int n) {
        double[] x = new double[n];
        double[] y = new double[n];
        double[] z = new double[n];
        for (int k = 1; k < n; k++) {
            double len = Math.pow(10, -6 + 12 * rnd.nextDouble());
            x[k] = x[k - 1] + len * rnd.nextGaussian();
            y[k] = y[k - 1] + len * rnd.nextGaussian();
            z[k] = z[k - 1] + len * rnd.nextGaussian();
        }
        return columns(x, y, z);
    }

    /** The poses as nearest-matched pairs of a trajectory with itself (stamps 0, 1, 2, ... s). */
    private static AssociatedColumns columns(double[] x, double[] y, double[] z) {
        int n = x.length;
        double[] t = new double[n];
        double[] qw = new double[n];
        int[] index = new int[n];
        for (int k = 0; k < n; k++) {
            t[k] = k;
            qw[k] = 1.0;
            index[k] = k;
        }
        SpatialTrajectory traj = SpatialTrajectory.of(t, x, y, z, qw, new double[n], new double[n], new double[n]);
        return AssociatedColumns.matched(traj, traj, index, index, n, 0.0, Parallelism.SEQUENTIAL);
    }
}
