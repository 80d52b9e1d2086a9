package org.trajeval.core.eval;

import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.geom.RotationsAsTheyWere;
import org.trajeval.core.metric.RelativeMotion;

/**
 * The 3x3 ATE and RPE kernels of {@link AssociatedColumns} as they were before they moved to locals
 * (main at 4e1def5): matrices in arrays, products by {@link RelativeMotion#inverseTimes} and loops,
 * the angle by {@link RotationsAsTheyWere}. Reads the pairs only through their {@code PosePairs}
 * view (raw estimate, reference rotations and positions), so it shares no kernel code.
 */
final class MatrixKernelsAsTheyWere {
    private final AssociatedColumns pairs;
    private final boolean aligned;
    private final double[] rot;
    private final double[] trans;
    private final double scale;

    MatrixKernelsAsTheyWere(AssociatedColumns pairs, AlignmentTransform tf) {
        this.pairs = pairs;
        this.aligned = tf.model() != AlignmentModel.NONE;
        this.rot = tf.rotation();
        this.trans = tf.translation();
        this.scale = tf.scale();
    }

    /** @return {translation error (m), rotation error (rad)} of the ATE of pair k */
    double[] ate(int k) {
        double[] p = new double[3];
        double[] r = new double[9];
        alignedPose(k, p, r);
        double dx = p[0] - pairs.reference().x(k);
        double dy = p[1] - pairs.reference().y(k);
        double dz = p[2] - pairs.reference().z(k);
        double[] rr = new double[9];
        pairs.referenceRotation(k, rr, 0);
        double[] e = new double[9];
        for (int row = 0; row < 3; row++) {
            for (int c = 0; c < 3; c++) {
                e[3 * row + c] = r[row] * rr[c] + r[3 + row] * rr[3 + c] + r[6 + row] * rr[6 + c];
            }
        }
        return new double[] {Math.sqrt(dx * dx + dy * dy + dz * dz), RotationsAsTheyWere.angle(e, 0)};
    }

    /** @return {translation error (m), rotation error (rad)} of the RPE of pair (i, j) */
    double[] rpe(int i, int j) {
        double[] ri = new double[9];
        double[] rj = new double[9];
        double[] q = new double[12];
        double[] p = new double[12];
        double[] e = new double[12];
        pairs.referenceRotation(i, ri, 0);
        pairs.referenceRotation(j, rj, 0);
        RelativeMotion.inverseTimes(ri, pairs.reference().x(i), pairs.reference().y(i), pairs.reference().z(i), rj,
                pairs.reference().x(j), pairs.reference().y(j), pairs.reference().z(j), q);
        double[] pi = new double[3];
        double[] pj = new double[3];
        alignedPose(i, pi, ri);
        alignedPose(j, pj, rj);
        RelativeMotion.inverseTimes(ri, pi[0], pi[1], pi[2], rj, pj[0], pj[1], pj[2], p);
        RelativeMotion.inverseTimes(q, q[9], q[10], q[11], p, p[9], p[10], p[11], e);
        return new double[] {Math.sqrt(e[9] * e[9] + e[10] * e[10] + e[11] * e[11]), RotationsAsTheyWere.angle(e, 0)};
    }

    private void alignedPose(int k, double[] p, double[] r) {
        double x = pairs.estimate().x(k);
        double y = pairs.estimate().y(k);
        double z = pairs.estimate().z(k);
        double[] rp = new double[9];
        pairs.estimateRotation(k, rp, 0);
        if (!aligned) {
            p[0] = x;
            p[1] = y;
            p[2] = z;
            System.arraycopy(rp, 0, r, 0, 9);
            return;
        }
        double px = scale * x;
        double py = scale * y;
        double pz = scale * z;
        double[] mr = rot;
        p[0] = mr[0] * px + mr[1] * py + mr[2] * pz + trans[0];
        p[1] = mr[3] * px + mr[4] * py + mr[5] * pz + trans[1];
        p[2] = mr[6] * px + mr[7] * py + mr[8] * pz + trans[2];
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 3; col++) {
                r[3 * row + col] = mr[3 * row] * rp[col] + mr[3 * row + 1] * rp[3 + col] + mr[3 * row + 2] * rp[6 + col];
            }
        }
    }
}
