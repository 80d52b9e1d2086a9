package org.trajeval.core.metric;

import org.trajeval.core.geom.Rotations;
import org.trajeval.core.stats.ErrorStatistics;
import org.trajeval.core.traj.PoseSequence;

/**
 * RPE of the lesson and of evo: for a pair (i, j) with reference poses Q and estimate poses P,
 * E_ij = (Q_i^-1 Q_j)^-1 (P_i^-1 P_j); the translation error is |trans(E_ij)| (m), which equals
 * the norm of the difference of the two relative translations, and the rotation error is the
 * rotation angle of E_ij (rad).
 *
 * <p>Worked example (planar, by hand): Q_i = identity, Q_j = (1 m, 0, yaw 0); P_i = identity,
 * P_j = (1.1 m, 0.1 m, yaw 0.05 rad). Then E = Q_rel^-1 P_rel = (0.1 m, 0.1 m, 0.05 rad):
 * translation error sqrt(0.1^2 + 0.1^2) = 0.1414 m, rotation error 0.05 rad.
 */
public final class RelativePoseError {
    private RelativePoseError() {
    }

    /**
     * @param reference associated reference poses
     * @param estimate associated (aligned) estimate poses
     * @param stamps time of each associated pair (s)
     */
    public static RpeResult compute(PoseSequence reference, PoseSequence estimate, double[] stamps,
            RpeOptions options) {
        PoseSequence pairSource = options.pairsFrom() == PairsFrom.REFERENCE ? reference : estimate;
        PairIndices pairs = PairIndices.compute(pairSource, stamps, options.delta(), options.unit(),
                options.selection());
        int m = pairs.count();
        double[] trans = new double[m];
        double[] rot = new double[m];
        double[] full = new double[m];
        int[] first = new int[m];
        int[] second = new int[m];
        double[] ri = new double[9];
        double[] rj = new double[9];
        double[] q = new double[12];
        double[] p = new double[12];
        double[] e = new double[12];
        double[] refDist = PairIndices.accumulatedDistances(reference);
        double sumS = 0;
        double sumM = 0;
        for (int k = 0; k < m; k++) {
            int i = pairs.i(k);
            int j = pairs.j(k);
            first[k] = i;
            second[k] = j;
            RelativeMotion.between(reference, i, j, ri, rj, q);
            RelativeMotion.between(estimate, i, j, ri, rj, p);
            RelativeMotion.inverseTimes(q, q[9], q[10], q[11], p, p[9], p[10], p[11], e);
            trans[k] = Math.sqrt(e[9] * e[9] + e[10] * e[10] + e[11] * e[11]);
            rot[k] = Rotations.angle(e, 0);
            full[k] = RelativeMotion.distanceFromIdentity(e);
            sumS += stamps[j] - stamps[i];
            sumM += refDist[j] - refDist[i];
        }
        return new RpeResult(first, second, trans, rot, ErrorStatistics.of(trans), ErrorStatistics.of(rot),
                ErrorStatistics.of(full), m == 0 ? Double.NaN : sumS / m, m == 0 ? Double.NaN : sumM / m);
    }
}
