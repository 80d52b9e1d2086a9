package org.trajeval.core.align;

import org.ejml.data.DMatrixRMaj;
import org.ejml.dense.row.CommonOps_DDRM;
import org.ejml.dense.row.SingularOps_DDRM;
import org.ejml.dense.row.factory.DecompositionFactory_DDRM;
import org.ejml.interfaces.decomposition.SingularValueDecomposition_F64;
import org.trajeval.core.traj.PositionColumns;

/**
 * Umeyama's least-squares similarity between two 3D point sets (IEEE PAMI 1991), with EJML's
 * SVD: minimises sum |y_i - (c R x_i + t)|^2. Follows the paper's equations as evo does:
 * Sigma = (1/n) sum (y_i - mu_y)(x_i - mu_x)^T = U D V^T (singular values sorted descending),
 * S = diag(1, 1, -1) when det(U) det(V) < 0 (reflection-safe), R = U S V^T,
 * c = trace(D S) / sigma_x^2, t = mu_y - c R mu_x. The covariance must have rank >= 2.
 */
final class Umeyama {
    private Umeyama() {
    }

    /**
     * @param x source points (estimate), the first n read
     * @param y target points (reference)
     * @param mx mu_x, the centroid of the first n source points ({@link PositionColumns#centroid}, m)
     * @param my mu_y, the centroid of the first n target points (m)
     * @return {R (9, row-major), t (3), {c}} or {@code null} when the covariance has rank < 2
     */
    static double[][] fit(PositionColumns x, PositionColumns y, int n, boolean withScale, double[] mx, double[] my) {
        double sigmaX = 0;
        double[] cov = new double[9];
        for (int i = 0; i < n; i++) {
            double ex0 = x.x(i) - mx[0];
            double ex1 = x.y(i) - mx[1];
            double ex2 = x.z(i) - mx[2];
            sigmaX += ex0 * ex0 + ex1 * ex1 + ex2 * ex2;
            double ey0 = y.x(i) - my[0];
            double ey1 = y.y(i) - my[1];
            double ey2 = y.z(i) - my[2];
            cov[0] += ey0 * ex0;
            cov[1] += ey0 * ex1;
            cov[2] += ey0 * ex2;
            cov[3] += ey1 * ex0;
            cov[4] += ey1 * ex1;
            cov[5] += ey1 * ex2;
            cov[6] += ey2 * ex0;
            cov[7] += ey2 * ex1;
            cov[8] += ey2 * ex2;
        }
        sigmaX /= n;
        for (int k = 0; k < 9; k++) {
            cov[k] *= 1.0 / n;
        }
        DMatrixRMaj sigma = new DMatrixRMaj(3, 3, true, cov);
        SingularValueDecomposition_F64<DMatrixRMaj> svd = DecompositionFactory_DDRM.svd(3, 3, true, true, false);
        if (!svd.decompose(sigma)) {
            return null;
        }
        DMatrixRMaj u = svd.getU(null, false);
        DMatrixRMaj v = svd.getV(null, false);
        DMatrixRMaj w = svd.getW(null);
        SingularOps_DDRM.descendingOrder(u, false, w, v, false);
        int rank = 0;
        double eps = Math.ulp(1.0);
        for (int k = 0; k < 3; k++) {
            if (w.get(k, k) > eps) {
                rank++;
            }
        }
        if (rank < 2) {
            return null;
        }
        double[] s = {1, 1, 1};
        if (CommonOps_DDRM.det(u) * CommonOps_DDRM.det(v) < 0.0) {
            s[2] = -1;
        }
        double[] rot = new double[9];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                double sum = 0;
                for (int k = 0; k < 3; k++) {
                    sum += u.get(r, k) * s[k] * v.get(c, k);
                }
                rot[3 * r + c] = sum;
            }
        }
        double scale = 1.0;
        if (withScale) {
            double tr = 0;
            for (int k = 0; k < 3; k++) {
                tr += w.get(k, k) * s[k];
            }
            scale = 1.0 / sigmaX * tr;
        }
        double[] t = new double[3];
        for (int r = 0; r < 3; r++) {
            t[r] = my[r] - scale * (rot[3 * r] * mx[0] + rot[3 * r + 1] * mx[1] + rot[3 * r + 2] * mx[2]);
        }
        return new double[][] {rot, t, {scale}};
    }
}
