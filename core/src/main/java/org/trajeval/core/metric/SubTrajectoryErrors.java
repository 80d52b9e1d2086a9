package org.trajeval.core.metric;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.trajeval.core.traj.PoseSequence;

/**
 * Relative error per sub-trajectory length, the box plots of rpg_trajectory_evaluation (Zhang and
 * Scaramuzza, IROS 2018): for each length L, the segments {@link SegmentSearch} finds (KITTI's
 * rule, shared with {@link LengthNormalisedDrift}), each giving |trans(E)| / L x 100 (%) and
 * angle(E) / L (deg/m), with E = (P_f^-1 P_l)^-1 (Q_f^-1 Q_l) (P estimate, Q reference). Unlike
 * the KITTI headline (a mean), every segment's value is kept. Worked example: a straight reference
 * with a pose every metre and an estimate stretched by 10 % give, for L = 2 m, segments of 3 poses
 * (the first pose beyond 2 m), |trans(E)| = 0.3 m and 0.3 / 2 x 100 = 15 %.
 *
 * @param perLength the segments per length, in the order of the lengths
 * @param stepFrames poses between segment starts
 */
public record SubTrajectoryErrors(List<AtLength> perLength, int stepFrames) {

    /** Fractions of the reference path used when no lengths are given (rpg's default). */
    private static final double[] DEFAULT_FRACTIONS = {0.1, 0.2, 0.3, 0.4, 0.5};
    /** Most segment starts per length: longer paths start a segment every ceil(n / this) poses. */
    public static final int MAX_STARTS = 5000;

    /** @throws IllegalArgumentException on a step below 1 */
    public SubTrajectoryErrors {
        perLength = List.copyOf(perLength);
        if (stepFrames < 1) {
            throw new IllegalArgumentException("segment step must be >= 1 pose, found " + stepFrames);
        }
    }

    /**
     * The segments of one length.
     *
     * @param lengthM sub-trajectory length L (m)
     * @param first start pose of each segment
     * @param transPct |trans(E)| / L x 100 per segment (%)
     * @param rotDegPerM angle(E) / L per segment (deg/m)
     */
    public record AtLength(double lengthM, int[] first, double[] transPct, double[] rotDegPerM) {
        /** @throws IllegalArgumentException when the arrays differ in length or L is not positive */
        public AtLength {
            if (first.length != transPct.length || transPct.length != rotDegPerM.length) {
                throw new IllegalArgumentException("segment arrays differ in length");
            }
            if (!(lengthM > 0) || !Double.isFinite(lengthM)) {
                throw new IllegalArgumentException("sub-trajectory length must be > 0 m, found " + lengthM);
            }
        }

        /** @return number of segments */
        public int size() {
            return first.length;
        }
    }

    /**
     * @param lengthsM sub-trajectory lengths (m, each &gt; 0), or null for 10, 20, 30, 40 and 50 % of
     *     the reference path
     * @return the errors, with a start every ceil(n / {@link #MAX_STARTS}) poses (every pose up to
     *     5000 poses); none when the reference does not move
     */
    public static SubTrajectoryErrors compute(PoseSequence reference, PoseSequence estimate, double[] lengthsM) {
        double[] dist = PairIndices.accumulatedDistances(reference);
        int n = reference.size();
        double total = n == 0 ? 0.0 : dist[n - 1];
        double[] lengths;
        if (lengthsM != null) {
            lengths = lengthsM.clone();
        } else if (total > 0) {
            lengths = new double[DEFAULT_FRACTIONS.length];
            for (int i = 0; i < lengths.length; i++) {
                lengths[i] = DEFAULT_FRACTIONS[i] * total;
            }
        } else {
            lengths = new double[0];
        }
        int step = Math.max(1, (n + MAX_STARTS - 1) / MAX_STARTS);
        int starts = (n + step - 1) / step;
        int[][] first = new int[lengths.length][starts];
        double[][] trans = new double[lengths.length][starts];
        double[][] rot = new double[lengths.length][starts];
        int[] count = new int[lengths.length];
        SegmentSearch.forEach(reference, estimate, dist, lengths, step, (li, f, l, tm, rr) -> {
            int k = count[li]++;
            first[li][k] = f;
            trans[li][k] = 100.0 * tm / lengths[li];
            rot[li][k] = Math.toDegrees(rr) / lengths[li];
        });
        List<AtLength> out = new ArrayList<>();
        for (int li = 0; li < lengths.length; li++) {
            int k = count[li];
            out.add(new AtLength(lengths[li], Arrays.copyOf(first[li], k), Arrays.copyOf(trans[li], k),
                    Arrays.copyOf(rot[li], k)));
        }
        return new SubTrajectoryErrors(out, step);
    }
}
