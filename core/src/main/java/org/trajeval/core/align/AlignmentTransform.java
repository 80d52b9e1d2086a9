package org.trajeval.core.align;

import org.trajeval.core.traj.PoseSequence;

/**
 * A similarity transform applied to whole poses: position p -> s R p + t (m), orientation
 * R_pose -> R R_pose. For rigid models s = 1.
 *
 * @param model the model that produced it
 * @param rotation R, 9 values row-major
 * @param translation t (m), 3 values
 * @param scale s (dimensionless, > 0)
 * @param posesUsed number of associated poses the fit used
 */
public record AlignmentTransform(AlignmentModel model, double[] rotation, double[] translation, double scale,
        int posesUsed) {

    /** @throws IllegalArgumentException on wrong array sizes or a non-positive scale */
    public AlignmentTransform {
        if (rotation.length != 9 || translation.length != 3) {
            throw new IllegalArgumentException("rotation needs 9 values and translation 3");
        }
        if (!(scale > 0.0)) {
            throw new IllegalArgumentException("scale must be positive, got " + scale);
        }
        rotation = rotation.clone();
        translation = translation.clone();
    }

    /** @return the identity (model NONE) */
    public static AlignmentTransform identity(int posesUsed) {
        return new AlignmentTransform(AlignmentModel.NONE, new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1},
                new double[3], 1.0, posesUsed);
    }

    @Override
    public double[] rotation() {
        return rotation.clone();
    }

    @Override
    public double[] translation() {
        return translation.clone();
    }

    /** @return rotation as 3 rows of 3 */
    public double[][] rotationRows() {
        return new double[][] {{rotation[0], rotation[1], rotation[2]}, {rotation[3], rotation[4], rotation[5]},
            {rotation[6], rotation[7], rotation[8]}};
    }

    /**
     * Applies the transform to every pose: p' = R (s p) + t, R' = R R_pose (evo's order: scale
     * first, then the rigid part).
     */
    public PoseSequence apply(PoseSequence poses) {
        if (model == AlignmentModel.NONE) {
            return poses;
        }
        int n = poses.size();
        double[] x = new double[n];
        double[] y = new double[n];
        double[] z = new double[n];
        double[] r = new double[9 * n];
        double[] m = rotation;
        double[] rp = new double[9];
        for (int i = 0; i < n; i++) {
            double px = scale * poses.x(i);
            double py = scale * poses.y(i);
            double pz = scale * poses.z(i);
            x[i] = m[0] * px + m[1] * py + m[2] * pz + translation[0];
            y[i] = m[3] * px + m[4] * py + m[5] * pz + translation[1];
            z[i] = m[6] * px + m[7] * py + m[8] * pz + translation[2];
            poses.rotation(i, rp, 0);
            int o = 9 * i;
            for (int row = 0; row < 3; row++) {
                for (int col = 0; col < 3; col++) {
                    r[o + 3 * row + col] = m[3 * row] * rp[col] + m[3 * row + 1] * rp[3 + col]
                            + m[3 * row + 2] * rp[6 + col];
                }
            }
        }
        return PoseSequence.of(x, y, z, r);
    }
}
