package org.trajeval.core.metric;

import org.trajeval.core.geom.Rotations;
import org.trajeval.core.stats.ErrorStatistics;
import org.trajeval.core.traj.PoseSequence;

/**
 * ATE over associated (and aligned) poses: translation error e_k = |t_est,k - t_ref,k| (m) and
 * rotation error = angle of E_k = T_est,k^-1 T_ref,k (rad; the same angle as R_ref^T R_est), which
 * in SE(2) is |wrap(yaw_est - yaw_ref)|.
 * Example: every estimate 0.10 m to the left of the truth gives ATE-RMSE 0.10 m.
 */
public final class AbsoluteTrajectoryError {
    private AbsoluteTrajectoryError() {
    }

    /** @return per-pose errors and their statistics */
    public static AteResult compute(PoseSequence reference, PoseSequence estimate) {
        int n = estimate.size();
        double[] trans = new double[n];
        double[] rot = new double[n];
        double[] rr = new double[9];
        double[] re = new double[9];
        double[] e = new double[12];
        double[] full = new double[n];
        for (int k = 0; k < n; k++) {
            double dx = estimate.x(k) - reference.x(k);
            double dy = estimate.y(k) - reference.y(k);
            double dz = estimate.z(k) - reference.z(k);
            trans[k] = Math.sqrt(dx * dx + dy * dy + dz * dz);
            reference.rotation(k, rr, 0);
            estimate.rotation(k, re, 0);
            // E_k = T_est^-1 T_ref (evo's order; its angle equals that of T_ref^-1 T_est)
            RelativeMotion.inverseTimes(re, estimate.x(k), estimate.y(k), estimate.z(k), rr, reference.x(k),
                    reference.y(k), reference.z(k), e);
            rot[k] = Rotations.angle(e, 0);
            full[k] = RelativeMotion.distanceFromIdentity(e);
        }
        return new AteResult(trans, rot, ErrorStatistics.of(trans), ErrorStatistics.of(rot), ErrorStatistics.of(full));
    }
}
