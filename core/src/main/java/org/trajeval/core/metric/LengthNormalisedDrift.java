package org.trajeval.core.metric;

import java.util.ArrayList;
import java.util.List;
import org.trajeval.core.geom.Rotations;
import org.trajeval.core.traj.PoseSequence;

/**
 * KITTI odometry drift (Geiger et al., CVPR 2012, devkit {@code evaluate_odometry}): segments
 * start every {@code step} frames; for start f and length L the end is the first frame l whose
 * reference path distance from f exceeds L; E = (P_f^-1 P_l)^-1 (Q_f^-1 Q_l); the segment's
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
        double totalT = 0;
        double totalR = 0;
        int total = 0;
        double[] ri = new double[9];
        double[] rj = new double[9];
        double[] q = new double[12];
        double[] p = new double[12];
        double[] e = new double[12];
        int[] last = new int[lengths.length];
        for (int f = 0; f < n; f += options.stepFrames()) {
            for (int li = 0; li < lengths.length; li++) {
                double target = dist[f] + lengths[li];
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
                double t = Math.sqrt(e[9] * e[9] + e[10] * e[10] + e[11] * e[11]) / lengths[li];
                double r = Rotations.angle(e, 0) / lengths[li];
                sumT[li] += t;
                sumR[li] += r;
                cnt[li]++;
                totalT += t;
                totalR += r;
                total++;
            }
        }
        List<DriftResult.AtLength> per = new ArrayList<>();
        for (int li = 0; li < lengths.length; li++) {
            per.add(new DriftResult.AtLength(lengths[li], cnt[li] == 0 ? Double.NaN : 100.0 * sumT[li] / cnt[li],
                    cnt[li] == 0 ? Double.NaN : Math.toDegrees(sumR[li] / cnt[li]), cnt[li]));
        }
        return new DriftResult(total == 0 ? Double.NaN : 100.0 * totalT / total,
                total == 0 ? Double.NaN : Math.toDegrees(totalR / total), total, options.stepFrames(), per,
                n == 0 ? 0.0 : dist[n - 1]);
    }
}
