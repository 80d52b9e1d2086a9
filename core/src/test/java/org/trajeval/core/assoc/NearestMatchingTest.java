package org.trajeval.core.assoc;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.junit.jupiter.api.Test;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.Trajectory;

/**
 * The nearest matching in chunks with a galloping search ({@link NearestMatching}) gives the pairs
 * of the search it replaced (a bisection from the last answer to the end, one pass over every
 * stamp): that loop is kept below, verbatim, as the reference.
 */
class NearestMatchingTest {

    @Test
    void gallopingFindsTheFirstGreaterStampAsBisectionDoes() {
        Random rnd = new Random(31);
        for (int trial = 0; trial < 200; trial++) {
            double[] t = stamps(rnd, 1 + rnd.nextInt(3000), 0.3); // runs of equal stamps, irregular steps
            double offset = trial % 2 == 0 ? 0.0 : -0.37 + trial;
            PlanarTrajectory traj = trajectory(t);
            double[] a = new double[t.length]; // the stamps the old search was given
            for (int k = 0; k < t.length; k++) {
                a[k] = t[k] + offset;
            }
            for (int q = 0; q < 200; q++) {
                double v = a[0] - 1 + (a[a.length - 1] - a[0] + 2) * rnd.nextDouble();
                if (q % 4 == 0) {
                    v = a[rnd.nextInt(a.length)]; // exactly a stamp (ties: the first strictly greater)
                }
                int expected = upperBoundAsItWas(a, v, 0);
                // any start at or below the answer whose predecessors are <= v gives it
                int from = expected == 0 ? 0 : rnd.nextInt(expected + 1);
                assertEquals(expected, NearestMatching.upperBound(traj, offset, v, from), "trial " + trial + " v " + v);
            }
        }
    }

    @Test
    void chunksRunInAnyOrderOnAnyThreadGiveThePairsOfOnePass() throws Exception {
        Random rnd = new Random(5);
        ExecutorService pool = Executors.newFixedThreadPool(3);
        try {
            // 200 003 and 70 001 stamps: chunks of 65 536 cut both unevenly; the shorter trajectory
            // is the estimate in one case and the reference in the other, with both offset signs
            PlanarTrajectory a = trajectory(stamps(rnd, 200_003, 0.1));
            PlanarTrajectory b = trajectory(stamps(rnd, 70_001, 0.0));
            for (double offset : new double[] {0.0, 0.37, -1.1}) {
                for (double maxDiff : new double[] {0.002, 0.01, 0.5}) {
                    for (Trajectory[] pair : new Trajectory[][] {{a, b}, {b, a}}) {
                        AssociationOptions o = new AssociationOptions(AssociationMethod.NEAREST, maxDiff, offset,
                                OverlapPolicy.CROP, MaxGap.DEFAULT);
                        int[][] expected = nearestAsItWas(pair[0], pair[1], o);
                        assertTrue(expected[0].length > 1000, "the case pairs poses");
                        String what = "offset " + offset + " max diff " + maxDiff + " ref " + pair[0].size();
                        same(expected, TimeAssociation.nearestPairs(pair[0], pair[1], o, "r", "e"), what);
                        same(expected, TimeAssociation.nearestPairs(pair[0], pair[1], o, "r", "e", backwards()),
                                what + " backwards");
                        same(expected, TimeAssociation.nearestPairs(pair[0], pair[1], o, "r", "e", on(pool)),
                                what + " on 3 threads");
                    }
                }
            }
        } finally {
            pool.shutdownNow();
        }
    }

    private static void same(int[][] expected, TimeAssociation.NearestPairs np, String what) {
        assertEquals(expected[0].length, np.count(), what);
        assertArrayEquals(expected[0], Arrays.copyOf(np.reference(), np.count()), what + " reference");
        assertArrayEquals(expected[1], Arrays.copyOf(np.estimate(), np.count()), what + " estimate");
    }

    /** The chunks last to first. */
    private static IndexTasks backwards() {
        return (tasks, task) -> {
            for (int c = tasks - 1; c >= 0; c--) {
                task.accept(c);
            }
        };
    }

    /** Every chunk a task of its own on the pool. */
    private static IndexTasks on(ExecutorService pool) {
        return (tasks, task) -> {
            Future<?>[] f = new Future<?>[tasks];
            for (int c = 0; c < tasks; c++) {
                int chunk = c;
                f[c] = pool.submit(() -> task.accept(chunk));
            }
            for (Future<?> x : f) {
                try {
                    x.get();
                } catch (Exception e) {
                    throw new AssertionError(e);
                }
            }
        };
    }

    /** Non-decreasing stamps from 0 with steps of 0.005-0.015 s, a step of 0 with probability {@code repeat}. */
    private static double[] stamps(Random rnd, int n, double repeat) {
        double[] t = new double[n];
        for (int i = 1; i < n; i++) {
            t[i] = t[i - 1] + (rnd.nextDouble() < repeat ? 0.0 : 0.005 + 0.01 * rnd.nextDouble());
        }
        return t;
    }

    private static PlanarTrajectory trajectory(double[] t) {
        return PlanarTrajectory.of(t, new double[t.length], new double[t.length], new double[t.length]);
    }

    // ---- the matching before the chunks and the galloping search (TimeAssociation at 9ab17c5), verbatim

    private static int[][] nearestAsItWas(Trajectory ref, Trajectory est, AssociationOptions o) {
        boolean estLonger = est.size() > ref.size();
        Trajectory shortTraj = estLonger ? ref : est;
        Trajectory longTraj = estLonger ? est : ref;
        double offsetLong = estLonger ? o.tOffsetS() : -o.tOffsetS();
        int ns = shortTraj.size();
        int nl = longTraj.size();
        double[] longStamps = new double[nl];
        for (int i = 0; i < nl; i++) {
            longStamps[i] = longTraj.t(i) + offsetLong;
        }
        double maxDiff = o.maxDiffS();
        int[] idxShort = new int[ns];
        int[] idxLong = new int[ns];
        int count = 0;
        int hint = 0;
        for (int i = 0; i < ns; i++) {
            double s = shortTraj.t(i);
            if (s < longStamps[0] - maxDiff || s > longStamps[nl - 1] + maxDiff) {
                continue;
            }
            int k = upperBoundAsItWas(longStamps, s, hint);
            hint = k;
            if (k >= nl) {
                k = nl - 1;
            }
            double diffUb = longStamps[k] - s;
            double diffLb = k > 0 ? s - longStamps[k - 1] : Double.POSITIVE_INFINITY;
            int best;
            if (diffUb <= maxDiff && diffUb < diffLb) {
                best = k;
            } else if (diffLb <= maxDiff && diffLb <= diffUb) {
                best = k - 1;
            } else {
                continue;
            }
            idxShort[count] = i;
            idxLong[count++] = best;
        }
        int[] r = Arrays.copyOf(estLonger ? idxShort : idxLong, count);
        int[] e = Arrays.copyOf(estLonger ? idxLong : idxShort, count);
        return new int[][] {r, e};
    }

    private static int upperBoundAsItWas(double[] a, double v, int from) {
        int lo = from;
        int hi = a.length;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (a[mid] > v) {
                hi = mid;
            } else {
                lo = mid + 1;
            }
        }
        return lo;
    }
}
