package org.trajeval.core.eval;

import java.util.Arrays;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.assoc.InterpolatedReference;
import org.trajeval.core.geom.Rotations;
import org.trajeval.core.metric.RelativeMotion;
import org.trajeval.core.traj.PositionColumns;
import org.trajeval.core.traj.Trajectory;

/**
 * The 3x3 ATE and RPE kernels of {@link AssociatedColumns} (SE(3) pairs, and planar pairs whose
 * alignment is not a rotation about +z): the general path's operations in its order, as
 * straight-line code on locals. Aligned estimate p' = A (s p) + t, R' = A R_est (R' = R_est, p' = p
 * for model none); ATE |p'_k - p_ref,k| (m) and the angle of R'_k^T R_ref,k (rad); RPE of a pair
 * (i, j): E = (Q_i^-1 Q_j)^-1 (P'_i^-1 P'_j) with inv(A) B = [R_A^T R_B, R_A^T t_B + (-(R_A^T t_A))]
 * (evo's order, {@link RelativeMotion#inverseTimes}), |trans(E)| (m) and the angle of E (rad,
 * {@link Rotations#angle(double, double, double, double, double, double, double, double, double)}).
 *
 * <p>Every pose of an RPE pass is met twice, as the end pose j of one pair and as the start pose i
 * of a later one. {@link Window} keeps the reference pose and the aligned estimate pose of the poses
 * a thread met last (a direct-mapped cache over pose indices, 192 B per slot, 192 KiB per thread), so
 * each is computed once when pairs move forward less than {@value Window#SLOTS} poses apart; the
 * values are the same either way.
 */
final class SpatialErrors {
    private final AssociatedColumns pairs;
    private final Trajectory est;
    private final PositionColumns refPositions;
    /** The ATE rotation errors the RPE fills for its start poses, or null (see {@link AssociatedColumns}). */
    private final double[] ateRotation;
    private final boolean aligned;
    private final double a00;
    private final double a01;
    private final double a02;
    private final double a10;
    private final double a11;
    private final double a12;
    private final double a20;
    private final double a21;
    private final double a22;
    private final double t0;
    private final double t1;
    private final double t2;
    private final double scale;

    SpatialErrors(AssociatedColumns pairs, Trajectory est, double[] ateRotation, AlignmentTransform tf) {
        this.pairs = pairs;
        this.est = est;
        this.refPositions = pairs.reference();
        this.ateRotation = ateRotation;
        this.aligned = tf.model() != AlignmentModel.NONE;
        double[] a = tf.rotation();
        double[] t = tf.translation();
        a00 = a[0];
        a01 = a[1];
        a02 = a[2];
        a10 = a[3];
        a11 = a[4];
        a12 = a[5];
        a20 = a[6];
        a21 = a[7];
        a22 = a[8];
        t0 = t[0];
        t1 = t[1];
        t2 = t[2];
        scale = tf.scale();
    }

    /** The ATE of pair k into {@code s.transError} (m) and {@code s.rotError} (rad). */
    void ate(int k, AssociatedColumns.Scratch s) {
        int e = pairs.estimateIndex(k);
        double px = est.x(e);
        double py = est.y(e);
        double pz = est.z(e);
        if (aligned) { // p' = A (s p) + t
            double sx = scale * px;
            double sy = scale * py;
            double sz = scale * pz;
            px = dot(a00, a01, a02, sx, sy, sz) + t0;
            py = dot(a10, a11, a12, sx, sy, sz) + t1;
            pz = dot(a20, a21, a22, sx, sy, sz) + t2;
        }
        double dx = px - refPositions.x(k);
        double dy = py - refPositions.y(k);
        double dz = pz - refPositions.z(k);
        s.transError = Math.sqrt(dx * dx + dy * dy + dz * dz);
        double known = ateRotation == null ? Double.NaN : ateRotation[k];
        if (!Double.isNaN(known)) {
            s.rotError = known;
            return;
        }
        double[] m = s.ri;
        est.rotation(e, m, 0);
        double e00 = m[0];
        double e01 = m[1];
        double e02 = m[2];
        double e10 = m[3];
        double e11 = m[4];
        double e12 = m[5];
        double e20 = m[6];
        double e21 = m[7];
        double e22 = m[8];
        if (aligned) { // R' = A R_est
            double n00 = dot(a00, a01, a02, e00, e10, e20);
            double n01 = dot(a00, a01, a02, e01, e11, e21);
            double n02 = dot(a00, a01, a02, e02, e12, e22);
            double n10 = dot(a10, a11, a12, e00, e10, e20);
            double n11 = dot(a10, a11, a12, e01, e11, e21);
            double n12 = dot(a10, a11, a12, e02, e12, e22);
            double n20 = dot(a20, a21, a22, e00, e10, e20);
            double n21 = dot(a20, a21, a22, e01, e11, e21);
            double n22 = dot(a20, a21, a22, e02, e12, e22);
            e00 = n00;
            e01 = n01;
            e02 = n02;
            e10 = n10;
            e11 = n11;
            e12 = n12;
            e20 = n20;
            e21 = n21;
            e22 = n22;
        }
        pairs.referenceRotation(k, m, 0, s);
        s.rotError = angleOfTransposeTimes(e00, e01, e02, e10, e11, e12, e20, e21, e22, m[0], m[1], m[2], m[3], m[4],
                m[5], m[6], m[7], m[8]);
    }

    /**
     * The ATE of pairs [from, to) into {@code trans[k]} (m) and {@code rot[k]} (rad), as {@link #ate}
     * gives them. A pose whose rotation error the RPE pass left takes only its translation; the
     * others go two at a time through the window and {@link Rotations#angles}, so the two angles'
     * long chains overlap.
     */
    void ateInto(int from, int to, double[] trans, double[] rot, AssociatedColumns.Scratch s) {
        Window w = s.spatialWindow();
        double[] v = w.v;
        double[] two = s.angles;
        int waiting = -1; // a pose without its rotation error, waiting for a second one
        for (int k = from; k < to; k++) {
            if (ateRotation != null && !Double.isNaN(ateRotation[k])) {
                ateInto(k, trans, rot, s);
                continue;
            }
            if (waiting < 0) {
                waiting = k;
                continue;
            }
            int o = w.slot(this, waiting, s);
            int n = w.slot(this, k, s);
            trans[waiting] = distance(v, o);
            trans[k] = distance(v, n);
            // R'^T R_ref of poses waiting and k: rotations at v[o + 12] and v[o]
            Rotations.angles(dot(v[o + 12], v[o + 15], v[o + 18], v[o], v[o + 3], v[o + 6]),
                    dot(v[o + 12], v[o + 15], v[o + 18], v[o + 1], v[o + 4], v[o + 7]),
                    dot(v[o + 12], v[o + 15], v[o + 18], v[o + 2], v[o + 5], v[o + 8]),
                    dot(v[o + 13], v[o + 16], v[o + 19], v[o], v[o + 3], v[o + 6]),
                    dot(v[o + 13], v[o + 16], v[o + 19], v[o + 1], v[o + 4], v[o + 7]),
                    dot(v[o + 13], v[o + 16], v[o + 19], v[o + 2], v[o + 5], v[o + 8]),
                    dot(v[o + 14], v[o + 17], v[o + 20], v[o], v[o + 3], v[o + 6]),
                    dot(v[o + 14], v[o + 17], v[o + 20], v[o + 1], v[o + 4], v[o + 7]),
                    dot(v[o + 14], v[o + 17], v[o + 20], v[o + 2], v[o + 5], v[o + 8]),
                    dot(v[n + 12], v[n + 15], v[n + 18], v[n], v[n + 3], v[n + 6]),
                    dot(v[n + 12], v[n + 15], v[n + 18], v[n + 1], v[n + 4], v[n + 7]),
                    dot(v[n + 12], v[n + 15], v[n + 18], v[n + 2], v[n + 5], v[n + 8]),
                    dot(v[n + 13], v[n + 16], v[n + 19], v[n], v[n + 3], v[n + 6]),
                    dot(v[n + 13], v[n + 16], v[n + 19], v[n + 1], v[n + 4], v[n + 7]),
                    dot(v[n + 13], v[n + 16], v[n + 19], v[n + 2], v[n + 5], v[n + 8]),
                    dot(v[n + 14], v[n + 17], v[n + 20], v[n], v[n + 3], v[n + 6]),
                    dot(v[n + 14], v[n + 17], v[n + 20], v[n + 1], v[n + 4], v[n + 7]),
                    dot(v[n + 14], v[n + 17], v[n + 20], v[n + 2], v[n + 5], v[n + 8]), two, 0);
            rot[waiting] = two[0];
            rot[k] = two[1];
            waiting = -1;
        }
        if (waiting >= 0) {
            ateInto(waiting, trans, rot, s);
        }
    }

    /** The ATE of pair k alone ({@link #ate}) into {@code trans[k]} (m) and {@code rot[k]} (rad). */
    private void ateInto(int k, double[] trans, double[] rot, AssociatedColumns.Scratch s) {
        ate(k, s);
        trans[k] = s.transError;
        rot[k] = s.rotError;
    }

    /** @return |p' - p_ref| (m) of the pose whose window values start at v[o] */
    private static double distance(double[] v, int o) {
        double dx = v[o + 21] - v[o + 9];
        double dy = v[o + 22] - v[o + 10];
        double dz = v[o + 23] - v[o + 11];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /**
     * The RPE of pair (i, j) into {@code s.transError} (m) and {@code s.rotError} (rad); for SE(3)
     * pairs also the ATE rotation error of pose i, from the rotations in hand.
     */
    void rpe(int i, int j, AssociatedColumns.Scratch s) {
        Window w = s.spatialWindow();
        int o = w.slot(this, i, s);
        double[] v = w.v;
        // pose i: reference rotation f and position t, aligned estimate rotation b and position p
        final double f00 = v[o];
        final double f01 = v[o + 1];
        final double f02 = v[o + 2];
        final double f10 = v[o + 3];
        final double f11 = v[o + 4];
        final double f12 = v[o + 5];
        final double f20 = v[o + 6];
        final double f21 = v[o + 7];
        final double f22 = v[o + 8];
        final double tx = v[o + 9];
        final double ty = v[o + 10];
        final double tz = v[o + 11];
        final double b00 = v[o + 12];
        final double b01 = v[o + 13];
        final double b02 = v[o + 14];
        final double b10 = v[o + 15];
        final double b11 = v[o + 16];
        final double b12 = v[o + 17];
        final double b20 = v[o + 18];
        final double b21 = v[o + 19];
        final double b22 = v[o + 20];
        final double px = v[o + 21];
        final double py = v[o + 22];
        final double pz = v[o + 23];
        o = w.slot(this, j, s);
        v = w.v;
        // pose j: reference rotation g and position u, aligned estimate rotation c and position r
        final double g00 = v[o];
        final double g01 = v[o + 1];
        final double g02 = v[o + 2];
        final double g10 = v[o + 3];
        final double g11 = v[o + 4];
        final double g12 = v[o + 5];
        final double g20 = v[o + 6];
        final double g21 = v[o + 7];
        final double g22 = v[o + 8];
        final double ux = v[o + 9];
        final double uy = v[o + 10];
        final double uz = v[o + 11];
        final double c00 = v[o + 12];
        final double c01 = v[o + 13];
        final double c02 = v[o + 14];
        final double c10 = v[o + 15];
        final double c11 = v[o + 16];
        final double c12 = v[o + 17];
        final double c20 = v[o + 18];
        final double c21 = v[o + 19];
        final double c22 = v[o + 20];
        final double rx = v[o + 21];
        final double ry = v[o + 22];
        final double rz = v[o + 23];
        // Q = inv(Ref_i) Ref_j
        double q00 = dot(f00, f10, f20, g00, g10, g20);
        double q01 = dot(f00, f10, f20, g01, g11, g21);
        double q02 = dot(f00, f10, f20, g02, g12, g22);
        double q10 = dot(f01, f11, f21, g00, g10, g20);
        double q11 = dot(f01, f11, f21, g01, g11, g21);
        double q12 = dot(f01, f11, f21, g02, g12, g22);
        double q20 = dot(f02, f12, f22, g00, g10, g20);
        double q21 = dot(f02, f12, f22, g01, g11, g21);
        double q22 = dot(f02, f12, f22, g02, g12, g22);
        double qx = dot(f00, f10, f20, ux, uy, uz) + -dot(f00, f10, f20, tx, ty, tz);
        double qy = dot(f01, f11, f21, ux, uy, uz) + -dot(f01, f11, f21, tx, ty, tz);
        double qz = dot(f02, f12, f22, ux, uy, uz) + -dot(f02, f12, f22, tx, ty, tz);
        // P = inv(P'_i) P'_j
        double p00 = dot(b00, b10, b20, c00, c10, c20);
        double p01 = dot(b00, b10, b20, c01, c11, c21);
        double p02 = dot(b00, b10, b20, c02, c12, c22);
        double p10 = dot(b01, b11, b21, c00, c10, c20);
        double p11 = dot(b01, b11, b21, c01, c11, c21);
        double p12 = dot(b01, b11, b21, c02, c12, c22);
        double p20 = dot(b02, b12, b22, c00, c10, c20);
        double p21 = dot(b02, b12, b22, c01, c11, c21);
        double p22 = dot(b02, b12, b22, c02, c12, c22);
        double sx = dot(b00, b10, b20, rx, ry, rz) + -dot(b00, b10, b20, px, py, pz);
        double sy = dot(b01, b11, b21, rx, ry, rz) + -dot(b01, b11, b21, px, py, pz);
        double sz = dot(b02, b12, b22, rx, ry, rz) + -dot(b02, b12, b22, px, py, pz);
        // E = inv(Q) P
        double ex = dot(q00, q10, q20, sx, sy, sz) + -dot(q00, q10, q20, qx, qy, qz);
        double ey = dot(q01, q11, q21, sx, sy, sz) + -dot(q01, q11, q21, qx, qy, qz);
        double ez = dot(q02, q12, q22, sx, sy, sz) + -dot(q02, q12, q22, qx, qy, qz);
        s.transError = Math.sqrt(ex * ex + ey * ey + ez * ez);
        if (ateRotation == null) {
            s.rotError = angleOfTransposeTimes(q00, q01, q02, q10, q11, q12, q20, q21, q22, p00, p01, p02, p10, p11,
                    p12, p20, p21, p22);
            return;
        }
        // with the ATE rotation error of pose i, the angle of R'_i^T R_ref,i: two angles side by side
        double[] two = s.angles;
        Rotations.angles(dot(q00, q10, q20, p00, p10, p20), dot(q00, q10, q20, p01, p11, p21),
                dot(q00, q10, q20, p02, p12, p22), dot(q01, q11, q21, p00, p10, p20), dot(q01, q11, q21, p01, p11, p21),
                dot(q01, q11, q21, p02, p12, p22), dot(q02, q12, q22, p00, p10, p20), dot(q02, q12, q22, p01, p11, p21),
                dot(q02, q12, q22, p02, p12, p22), dot(b00, b10, b20, f00, f10, f20), dot(b00, b10, b20, f01, f11, f21),
                dot(b00, b10, b20, f02, f12, f22), dot(b01, b11, b21, f00, f10, f20), dot(b01, b11, b21, f01, f11, f21),
                dot(b01, b11, b21, f02, f12, f22), dot(b02, b12, b22, f00, f10, f20), dot(b02, b12, b22, f01, f11, f21),
                dot(b02, b12, b22, f02, f12, f22), two, 0);
        s.rotError = two[0];
        ateRotation[i] = two[1];
    }

    /**
     * Writes pose k's reference rotation (9, row-major) and position (3, m), then its aligned
     * estimate rotation R' (9) and position p' (3, m) into {@code v[o..o+24)}.
     */
    private void pose(int k, double[] v, int o, AssociatedColumns.Scratch s) {
        pairs.referenceRotationOnce(k, v, o, s);
        poseAfterRotation(k, v, o);
    }

    /** {@link #pose} of poses k and k + 1, into {@code v[o..o+24)} and {@code v[p..p+24)}, their reference rotations side by side. */
    private void poses(int k, double[] v, int o, int p, AssociatedColumns.Scratch s) {
        pairs.referenceRotationsOnce(k, v, o, p, s);
        poseAfterRotation(k, v, o);
        poseAfterRotation(k + 1, v, p);
    }

    /** The rest of {@link #pose} once the reference rotation is at {@code v[o..o+9)}. */
    private void poseAfterRotation(int k, double[] v, int o) {
        v[o + 9] = refPositions.x(k);
        v[o + 10] = refPositions.y(k);
        v[o + 11] = refPositions.z(k);
        int e = pairs.estimateIndex(k);
        est.rotation(e, v, o + 12);
        double px = est.x(e);
        double py = est.y(e);
        double pz = est.z(e);
        if (aligned) { // p' = A (s p) + t, R' = A R_est
            double sx = scale * px;
            double sy = scale * py;
            double sz = scale * pz;
            px = dot(a00, a01, a02, sx, sy, sz) + t0;
            py = dot(a10, a11, a12, sx, sy, sz) + t1;
            pz = dot(a20, a21, a22, sx, sy, sz) + t2;
            double e00 = v[o + 12];
            double e01 = v[o + 13];
            double e02 = v[o + 14];
            double e10 = v[o + 15];
            double e11 = v[o + 16];
            double e12 = v[o + 17];
            double e20 = v[o + 18];
            double e21 = v[o + 19];
            double e22 = v[o + 20];
            v[o + 12] = dot(a00, a01, a02, e00, e10, e20);
            v[o + 13] = dot(a00, a01, a02, e01, e11, e21);
            v[o + 14] = dot(a00, a01, a02, e02, e12, e22);
            v[o + 15] = dot(a10, a11, a12, e00, e10, e20);
            v[o + 16] = dot(a10, a11, a12, e01, e11, e21);
            v[o + 17] = dot(a10, a11, a12, e02, e12, e22);
            v[o + 18] = dot(a20, a21, a22, e00, e10, e20);
            v[o + 19] = dot(a20, a21, a22, e01, e11, e21);
            v[o + 20] = dot(a20, a21, a22, e02, e12, e22);
        }
        v[o + 21] = px;
        v[o + 22] = py;
        v[o + 23] = pz;
    }

    /** @return a0 b0 + a1 b1 + a2 b2, summed left to right */
    private static double dot(double a0, double a1, double a2, double b0, double b1, double b2) {
        return a0 * b0 + a1 * b1 + a2 * b2;
    }

    /** @return the rotation angle (rad) of A^T B, A and B given row by row ({@link Rotations#angle}) */
    private static double angleOfTransposeTimes(double a00, double a01, double a02, double a10, double a11,
            double a12, double a20, double a21, double a22, double b00, double b01, double b02, double b10,
            double b11, double b12, double b20, double b21, double b22) {
        return Rotations.angle(dot(a00, a10, a20, b00, b10, b20), dot(a00, a10, a20, b01, b11, b21),
                dot(a00, a10, a20, b02, b12, b22), dot(a01, a11, a21, b00, b10, b20), dot(a01, a11, a21, b01, b11, b21),
                dot(a01, a11, a21, b02, b12, b22), dot(a02, a12, a22, b00, b10, b20), dot(a02, a12, a22, b01, b11, b21),
                dot(a02, a12, a22, b02, b12, b22));
    }

    /**
     * The poses a thread met last, for one kernel instance: pose k in slot k mod {@value #SLOTS}, its
     * 24 values as {@link #pose} writes them. When the scratch says poses are asked in runs
     * ({@link AssociatedColumns.Scratch#posesInRuns}), a pose not held is computed together with the
     * next one ({@link #poses}: two slerps side by side). Bound to one kernel at a time (a new alignment makes a
     * new kernel): used with another, it forgets what it held.
     */
    static final class Window {
        /**
         * Number of slots (a power of two): 192 KiB of values. As many as the interpolated reference's
         * matrix cache ({@link InterpolatedReference.Cursor#SLOTS}), which the window's poses skip.
         */
        static final int SLOTS = 1024;
        private final double[] v = new double[24 * SLOTS];
        private final int[] pose = new int[SLOTS];
        private SpatialErrors owner;

        /** @return the offset in {@code v} of pose k's values, computed unless the slot holds them */
        int slot(SpatialErrors kernel, int k, AssociatedColumns.Scratch s) {
            if (owner != kernel) {
                Arrays.fill(pose, -1);
                owner = kernel;
            }
            int slot = k & (SLOTS - 1);
            int o = 24 * slot;
            if (pose[slot] != k) {
                int next = (k + 1) & (SLOTS - 1);
                if (s.posesInRuns && k + 1 < kernel.pairs.size() && pose[next] != k + 1) {
                    kernel.poses(k, v, o, 24 * next, s);
                    pose[next] = k + 1;
                } else {
                    kernel.pose(k, v, o, s);
                }
                pose[slot] = k;
            }
            return o;
        }
    }
}
