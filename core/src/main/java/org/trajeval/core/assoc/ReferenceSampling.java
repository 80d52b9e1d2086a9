package org.trajeval.core.assoc;

import org.trajeval.core.traj.Trajectory;

/**
 * Sampling quality of a reference trajectory, for the lesson's Proposition 2 (interpolation
 * error <= A_max h^2 / 8).
 */
public final class ReferenceSampling {
    private ReferenceSampling() {
    }

    /** @return the largest gap t(k+1) - t(k) for from <= k < to (s); 0 for a single pose */
    public static double maxGap(Trajectory ref, int from, int to) {
        double h = 0.0;
        for (int k = from; k < to; k++) {
            h = Math.max(h, ref.t(k + 1) - ref.t(k));
        }
        return h;
    }

    /**
     * Largest acceleration norm of the reference over poses [from, to], estimated by second
     * divided differences: a_k = 2 (v_k - v_{k-1}) / (h_k + h_{k-1}), v_k = (p_{k+1} - p_k) / h_k
     * (m/s^2). With noisy ground truth this overestimates A_max (noise / h^2), which keeps the
     * bound conservative.
     */
    public static double maxAcceleration(Trajectory ref, int from, int to) {
        int lo = Math.max(from, 1);
        int hi = Math.min(to, ref.size() - 2);
        double aMax = 0.0;
        for (int k = lo; k <= hi; k++) {
            double h0 = ref.t(k) - ref.t(k - 1);
            double h1 = ref.t(k + 1) - ref.t(k);
            if (!(h0 > 0.0) || !(h1 > 0.0)) {
                continue; // a duplicate stamp (kept on request) says nothing about acceleration
            }
            double w = 2.0 / (h0 + h1);
            double ax = w * ((ref.x(k + 1) - ref.x(k)) / h1 - (ref.x(k) - ref.x(k - 1)) / h0);
            double ay = w * ((ref.y(k + 1) - ref.y(k)) / h1 - (ref.y(k) - ref.y(k - 1)) / h0);
            double az = w * ((ref.z(k + 1) - ref.z(k)) / h1 - (ref.z(k) - ref.z(k - 1)) / h0);
            aMax = Math.max(aMax, Math.sqrt(ax * ax + ay * ay + az * az));
        }
        return aMax;
    }
}
