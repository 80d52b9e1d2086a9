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

    /** @return the largest gap t(k+1) - t(k) <= limit for from <= k < to (s): the largest one bridged */
    public static double maxGapUpTo(Trajectory ref, int from, int to, double limit) {
        double h = 0.0;
        for (int k = from; k < to; k++) {
            double g = ref.t(k + 1) - ref.t(k);
            if (g <= limit) {
                h = Math.max(h, g);
            }
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
        double aMax2 = 0.0;
        if (lo > hi) {
            return 0.0;
        }
        double t0 = ref.t(lo - 1);
        double t1 = ref.t(lo);
        double vx0 = ref.x(lo) - ref.x(lo - 1);
        double vy0 = ref.y(lo) - ref.y(lo - 1);
        double vz0 = ref.z(lo) - ref.z(lo - 1);
        double h0 = t1 - t0;
        double inv0 = 1.0 / h0;
        for (int k = lo; k <= hi; k++) {
            double t2 = ref.t(k + 1);
            double h1 = t2 - t1;
            double dx = ref.x(k + 1) - ref.x(k);
            double dy = ref.y(k + 1) - ref.y(k);
            double dz = ref.z(k + 1) - ref.z(k);
            double inv1 = 1.0 / h1;
            if (h0 > 0.0 && h1 > 0.0) {
                // a duplicate stamp (kept on request) says nothing about acceleration: skipped
                double w = 2.0 / (h0 + h1);
                double ax = w * (dx * inv1 - vx0 * inv0);
                double ay = w * (dy * inv1 - vy0 * inv0);
                double az = w * (dz * inv1 - vz0 * inv0);
                aMax2 = Math.max(aMax2, ax * ax + ay * ay + az * az);
            }
            t1 = t2;
            h0 = h1;
            inv0 = inv1;
            vx0 = dx;
            vy0 = dy;
            vz0 = dz;
        }
        return Math.sqrt(aMax2);
    }
}
