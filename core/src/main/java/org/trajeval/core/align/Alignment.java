package org.trajeval.core.align;

import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.traj.PoseSequence;
import org.trajeval.core.traj.PositionColumns;

/** Fits an {@link AlignmentModel} that brings the estimate onto the reference. */
public final class Alignment {
    private Alignment() {
    }

    /**
     * Fits the model on associated poses (pair k: reference k, estimate k).
     *
     * @param nToAlign fit on the first n pairs; -1 for all
     * @param source name used in error messages (the estimate file)
     * @throws InputException DEGENERATE_ALIGNMENT when the points do not determine the transform
     *     (e.g. coincident points; collinear points for se3/sim3), TOO_FEW_POSES when fewer
     *     pairs than the model needs
     */
    public static AlignmentTransform fit(AlignmentModel model, PoseSequence reference, PoseSequence estimate,
            int nToAlign, String source) {
        return fit(model, PosePairs.of(reference, estimate), nToAlign, source);
    }

    /**
     * As {@link #fit(AlignmentModel, PoseSequence, PoseSequence, int, String)} on pairs read in
     * place (the same sums in the same order: the same bits).
     */
    public static AlignmentTransform fit(AlignmentModel model, PosePairs pairs, int nToAlign, String source) {
        return fit(model, pairs, nToAlign, source, null, null);
    }

    /** @return how many pairs, from the first, a fit with this {@code nToAlign} (-1: all) uses out of {@code size} */
    public static int pairsUsed(int nToAlign, int size) {
        return nToAlign < 0 ? size : Math.min(nToAlign, size);
    }

    /** @return whether the model's fit starts from the centroids of the positions it is fitted on */
    public static boolean usesCentroids(AlignmentModel model) {
        return model != AlignmentModel.NONE && model != AlignmentModel.ORIGIN;
    }

    /**
     * As {@link #fit(AlignmentModel, PosePairs, int, String)}, with the centroids (m) of the first
     * {@link #pairsUsed} estimate and reference positions computed beforehand (e.g. on two
     * threads) by {@link PositionColumns#centroid}, the fit's own sums: the same bits. Either may
     * be null (then the fit computes it); models that need none ignore them.
     */
    public static AlignmentTransform fit(AlignmentModel model, PosePairs pairs, int nToAlign, String source,
            double[] meanEst, double[] meanRef) {
        int n = pairsUsed(nToAlign, pairs.size());
        return switch (model) {
            case NONE -> AlignmentTransform.identity(0);
            case ORIGIN -> origin(pairs);
            case SE2, SIM2, POSYAW -> planar(model, pairs.reference(), pairs.estimate(), n, source, meanEst, meanRef);
            case SE3, SIM3 -> spatial(model, pairs.reference(), pairs.estimate(), n, source, meanEst, meanRef);
        };
    }

    /** T = T_ref,0 T_est,0^-1: R = R_ref0 R_est0^T, t = t_ref0 - R t_est0. */
    private static AlignmentTransform origin(PosePairs pairs) {
        PositionColumns ref = pairs.reference();
        PositionColumns est = pairs.estimate();
        double[] rr = new double[9];
        double[] re = new double[9];
        pairs.referenceRotation(0, rr, 0);
        pairs.estimateRotation(0, re, 0);
        double[] r = new double[9];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                // (R_ref0 R_est0^T)_ij = sum_k R_ref0[i][k] R_est0[j][k]
                r[3 * i + j] = rr[3 * i] * re[3 * j] + rr[3 * i + 1] * re[3 * j + 1] + rr[3 * i + 2] * re[3 * j + 2];
            }
        }
        // inverse translation of the estimate origin: -R_est0^T t_est0
        double[] te = {est.x(0), est.y(0), est.z(0)};
        double[] inv = new double[3];
        for (int i = 0; i < 3; i++) {
            inv[i] = -(re[i] * te[0] + re[3 + i] * te[1] + re[6 + i] * te[2]);
        }
        double[] t = new double[3];
        double[] tr = {ref.x(0), ref.y(0), ref.z(0)};
        for (int i = 0; i < 3; i++) {
            t[i] = rr[3 * i] * inv[0] + rr[3 * i + 1] * inv[1] + rr[3 * i + 2] * inv[2] + tr[i];
        }
        return new AlignmentTransform(AlignmentModel.ORIGIN, r, t, 1.0, 1);
    }

    /**
     * Closed-form planar fit on the xy coordinates of centred points e (estimate), g (reference):
     * a = sum (e_x g_x + e_y g_y), b = sum (e_x g_y - e_y g_x), theta = atan2(b, a) (a proper
     * rotation, never a reflection); sim2: s = sqrt(a^2 + b^2) / sum |e|^2; the translation is
     * mu_g - s R mu_e in xy, and for posyaw also in z (se2/sim2 leave z alone).
     */
    private static AlignmentTransform planar(AlignmentModel model, PositionColumns ref, PositionColumns est, int n,
            String source, double[] meanEst, double[] meanRef) {
        if (n < 2) {
            throw new InputException(source, 0, null, InputProblem.TOO_FEW_POSES,
                    model.name().toLowerCase() + " alignment needs at least 2 associated poses, got " + n, null);
        }
        double[] me = meanEst != null ? meanEst : est.centroid(n);
        double[] mg = meanRef != null ? meanRef : ref.centroid(n);
        double mex = me[0];
        double mey = me[1];
        double mgx = mg[0];
        double mgy = mg[1];
        double a = 0;
        double b = 0;
        double ee = 0;
        for (int i = 0; i < n; i++) {
            double ex = est.x(i) - mex;
            double ey = est.y(i) - mey;
            double gx = ref.x(i) - mgx;
            double gy = ref.y(i) - mgy;
            a += ex * gx + ey * gy;
            b += ex * gy - ey * gx;
            ee += ex * ex + ey * ey;
        }
        return planarFromSums(model, n, me, mg, a, b, ee, source);
    }

    /**
     * The planar closed form from its sums over n pairs of centred points e (estimate) and g
     * (reference): a = sum (e_x g_x + e_y g_y), b = sum (e_x g_y - e_y g_x), ee = sum |e|^2 (xy).
     *
     * @param meanEst mean estimate position (m), 3 values
     * @param meanRef mean reference position (m), 3 values
     * @throws InputException DEGENERATE_ALIGNMENT when ee = 0 or a = b = 0
     */
    public static AlignmentTransform planarFromSums(AlignmentModel model, int n, double[] meanEst, double[] meanRef,
            double a, double b, double ee, String source) {
        double norm = Math.hypot(a, b);
        if (!(ee > 0.0) || !(norm > 1e-12 * ee)) {
            throw new InputException(source, 0, null, InputProblem.DEGENERATE_ALIGNMENT,
                    model.name().toLowerCase() + " alignment is not determined: the " + n
                            + " estimate positions used do not spread in the xy plane (all at one point, or "
                            + "uncorrelated with the reference); use --align none or origin", null);
        }
        double theta = Math.atan2(b, a);
        double c = Math.cos(theta);
        double s = Math.sin(theta);
        double scale = model == AlignmentModel.SIM2 ? norm / ee : 1.0;
        double[] r = {c, -s, 0, s, c, 0, 0, 0, 1};
        double tx = meanRef[0] - scale * (c * meanEst[0] - s * meanEst[1]);
        double ty = meanRef[1] - scale * (s * meanEst[0] + c * meanEst[1]);
        double tz = model == AlignmentModel.POSYAW ? meanRef[2] - meanEst[2] : 0.0;
        return new AlignmentTransform(model, r, new double[] {tx, ty, tz}, scale, n);
    }

    private static AlignmentTransform spatial(AlignmentModel model, PositionColumns ref, PositionColumns est, int n,
            String source, double[] meanEst, double[] meanRef) {
        if (n < 3) {
            throw new InputException(source, 0, null, InputProblem.TOO_FEW_POSES,
                    model.name().toLowerCase() + " alignment needs at least 3 associated poses, got " + n, null);
        }
        double[][] fit = Umeyama.fit(est, ref, n, model == AlignmentModel.SIM3,
                meanEst != null ? meanEst : est.centroid(n), meanRef != null ? meanRef : ref.centroid(n));
        if (fit == null || !(fit[2][0] > 0.0)) {
            throw new InputException(source, 0, null, InputProblem.DEGENERATE_ALIGNMENT,
                    model.name().toLowerCase() + " alignment is not determined: the covariance of the " + n
                            + " estimate and reference positions has rank < 2 (points coincident or collinear); "
                            + "use --align none, origin or a planar model", null);
        }
        return new AlignmentTransform(model, fit[0], fit[1], fit[2][0], n);
    }
}
