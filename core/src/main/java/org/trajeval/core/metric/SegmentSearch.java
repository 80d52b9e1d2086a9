package org.trajeval.core.metric;

import org.trajeval.core.geom.Rotations;
import org.trajeval.core.traj.PoseSequence;

/**
 * The KITTI devkit's segments ({@code evaluate_odometry}: {@code lastFrameFromSegmentLength}),
 * shared by {@link LengthNormalisedDrift} (means) and {@link SubTrajectoryErrors} (every value):
 * starts f = 0, step, 2 step, ...; for a start f and a length L the end l is the first pose whose
 * reference path distance exceeds d_f + L (a start with no such pose gives no segment); with
 * P the estimate and Q the reference, E = (P_f^-1 P_l)^-1 (Q_f^-1 Q_l), and the segment's errors
 * are |trans(E)| (m) and angle(E) (rad). Linear in the number of poses per length: the end only
 * moves forward.
 */
final class SegmentSearch {
    private SegmentSearch() {
    }

    /** Receives one segment. */
    @FunctionalInterface
    interface Visitor {
        /**
         * @param lengthIndex index into the lengths
         * @param first start pose f
         * @param last end pose l
         * @param transErrorM |trans(E)| (m)
         * @param rotErrorRad angle(E) (rad)
         */
        void segment(int lengthIndex, int first, int last, double transErrorM, double rotErrorRad);
    }

    /**
     * Visits the segments start by start, and per start length by length (the devkit's order).
     *
     * @param dist cumulative reference path length per pose (m), {@link PairIndices#accumulatedDistances}
     * @param lengthsM segment lengths (m)
     * @param stepFrames poses between starts, &gt;= 1
     */
    static void forEach(PoseSequence reference, PoseSequence estimate, double[] dist, double[] lengthsM,
            int stepFrames, Visitor visitor) {
        int n = reference.size();
        double[] ri = new double[9];
        double[] rj = new double[9];
        double[] q = new double[12];
        double[] p = new double[12];
        double[] e = new double[12];
        int[] last = new int[lengthsM.length];
        for (int f = 0; f < n; f += stepFrames) {
            for (int li = 0; li < lengthsM.length; li++) {
                double target = dist[f] + lengthsM[li];
                int l = Math.max(last[li], f);
                while (l < n && !(dist[l] > target)) {
                    l++;
                }
                last[li] = l;
                if (l >= n) {
                    continue;
                }
                RelativeMotion.between(reference, f, l, ri, rj, q);
                RelativeMotion.between(estimate, f, l, ri, rj, p);
                RelativeMotion.inverseTimes(p, p[9], p[10], p[11], q, q[9], q[10], q[11], e);
                visitor.segment(li, f, l, Math.sqrt(e[9] * e[9] + e[10] * e[10] + e[11] * e[11]),
                        Rotations.angle(e, 0));
            }
        }
    }
}
