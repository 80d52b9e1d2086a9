package org.trajeval.core.metric;

import java.util.ArrayList;
import java.util.List;
import org.trajeval.core.traj.PoseSequence;

/**
 * KITTI odometry drift (Geiger et al., CVPR 2012, devkit {@code evaluate_odometry}): segments
 * as {@link SegmentSearch} finds them (a start every {@code step} frames; for start f and length L
 * the end is the first frame l whose reference path distance from f exceeds L);
 * E = (P_f^-1 P_l)^-1 (Q_f^-1 Q_l); the segment's
 * errors are |trans(E)| / L (reported x 100, %) and angle(E) / L (reported in deg/m). The
 * headline figures are the means over all segments of all lengths.
 */
public final class LengthNormalisedDrift {
    private LengthNormalisedDrift() {
    }

    /** @return the drift, with zero segments when the path is shorter than every length */
    public static DriftResult compute(PoseSequence reference, PoseSequence estimate, DriftOptions options) {
        double[] dist = PairIndices.accumulatedDistances(reference);
        double[] lengths = options.segmentLengthsM();
        int n = reference.size();
        double[] sumT = new double[lengths.length];
        double[] sumR = new double[lengths.length];
        int[] cnt = new int[lengths.length];
        double[] total = new double[3]; // sum of trans / L, sum of rot / L, count
        SegmentSearch.forEach(reference, estimate, dist, lengths, options.stepFrames(), (li, f, l, tm, rr) -> {
            double t = tm / lengths[li];
            double r = rr / lengths[li];
            sumT[li] += t;
            sumR[li] += r;
            cnt[li]++;
            total[0] += t;
            total[1] += r;
            total[2]++;
        });
        List<DriftResult.AtLength> per = new ArrayList<>();
        for (int li = 0; li < lengths.length; li++) {
            per.add(new DriftResult.AtLength(lengths[li], cnt[li] == 0 ? Double.NaN : 100.0 * sumT[li] / cnt[li],
                    cnt[li] == 0 ? Double.NaN : Math.toDegrees(sumR[li] / cnt[li]), cnt[li]));
        }
        int segments = (int) total[2];
        return new DriftResult(segments == 0 ? Double.NaN : 100.0 * total[0] / segments,
                segments == 0 ? Double.NaN : Math.toDegrees(total[1] / segments), segments, options.stepFrames(), per,
                n == 0 ? 0.0 : dist[n - 1]);
    }
}
