package org.trajeval.core.traj;

import org.trajeval.core.geom.Rotations;

/**
 * Projects SE(3) poses onto a plane as evo does: the coordinate normal to the plane is set to 0
 * and the rotation is replaced by the rotation about the normal by the matching angle of the
 * static x-y-z Euler decomposition (xy: yaw = atan2(r10, r00); xz: pitch = atan2(-r20,
 * sqrt(r00^2 + r10^2)), which folds headings beyond +-90 deg: a known limit of this convention).
 */
public final class PlaneProjection {
    private PlaneProjection() {
    }

    /** @return the projected poses */
    public static PoseSequence project(PoseSequence poses, Plane plane) {
        int n = poses.size();
        double[][] p = poses.positions();
        double[] r = poses.rotations();
        double[] out = new double[9 * n];
        for (int i = 0; i < n; i++) {
            int o = 9 * i;
            if (plane == Plane.XY) {
                p[2][i] = 0.0;
                Rotations.aboutZ(Rotations.yaw(r, o), out, o);
            } else {
                p[1][i] = 0.0;
                double a = Rotations.pitch(r, o);
                double c = Math.cos(a);
                double s = Math.sin(a);
                out[o] = c;
                out[o + 2] = s;
                out[o + 4] = 1.0;
                out[o + 6] = -s;
                out[o + 8] = c;
            }
        }
        return PoseSequence.of(p[0], p[1], p[2], out);
    }
}
