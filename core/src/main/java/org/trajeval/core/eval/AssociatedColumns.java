package org.trajeval.core.eval;

import java.util.Arrays;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.align.PosePairs;
import org.trajeval.core.assoc.InterpolatedReference;
import org.trajeval.core.geom.Rotations;
import org.trajeval.core.metric.RelativeMotion;
import org.trajeval.core.traj.PositionColumns;
import org.trajeval.core.traj.Trajectory;

/**
 * Associated poses without per-pose objects or copies: pair k is estimate pose e(k) of the
 * estimate trajectory (e(k) = k0 + k for interpolation, an index map for nearest matching) and
 * either the reference interpolated at its stamp (columns) or reference pose r(k) (index map).
 * Rotation matrices are derived on demand from the trajectories' own columns (yaw or
 * quaternion), bit for bit the matrices the general path materialises.
 *
 * <p>Once an alignment (s, R, t) is set, the per-pose errors are those of the general path, in
 * its operation order: aligned estimate p' = R (s p) + t, R' = R R_est; ATE
 * |p'_k - p_ref,k| (m) and the angle of R'_k^T R_ref,k (rad); RPE of a pair (i, j):
 * E = (Q_i^-1 Q_j)^-1 (P'_i^-1 P'_j), |trans(E)| (m) and the angle of E (rad). When both
 * trajectories are planar and the alignment is a rotation about +z, {@link PlanarErrors} computes
 * them from 2x2 blocks, the same operations without those on the matrices' zeros and ones (the
 * same bits); the 3x3 kernels here remain for SE(3) pairs and as its fallback.
 */
final class AssociatedColumns implements PosePairs {
    private final Trajectory ref;
    private final Trajectory est;
    private final InterpolatedReference interpolated;
    private final int[] refIndex;
    private final int[] estIndex;
    private final int k0;
    private final int m;
    private final double off;
    private final PositionColumns refPositions;
    private final PositionColumns estPositions;
    /**
     * ATE rotation errors (rad) computed by {@link #rpe} for its start pose i while the reference
     * rotation of i is in the thread's cache, NaN where not yet computed; only for an SE(3)
     * interpolated reference, whose rotations cost a slerp each (8 B per pose against a second slerp).
     */
    private final double[] ateRotation;
    private boolean aligned;
    /** The alignment's rotation A (row-major entries), translation t (m) and scale s. */
    private double a00 = 1.0;
    private double a01;
    private double a02;
    private double a10;
    private double a11 = 1.0;
    private double a12;
    private double a20;
    private double a21;
    private double a22 = 1.0;
    private double t0;
    private double t1;
    private double t2;
    private double scale = 1.0;
    /** The 2x2 kernels when the pairs and the alignment are planar; null otherwise. */
    private PlanarErrors planar;

    private AssociatedColumns(Trajectory ref, Trajectory est, InterpolatedReference interpolated, int[] refIndex,
            int[] estIndex, int k0, int m, double off) {
        this.ref = ref;
        this.est = est;
        this.interpolated = interpolated;
        this.refIndex = refIndex;
        this.estIndex = estIndex;
        this.k0 = k0;
        this.m = m;
        this.off = off;
        this.refPositions = interpolated != null ? interpolated : new Mapped(ref, refIndex, 0);
        this.estPositions = new Mapped(est, estIndex, k0);
        if (interpolated != null && interpolated.isSpatial()) {
            this.ateRotation = new double[m];
            Arrays.fill(ateRotation, Double.NaN);
        } else {
            this.ateRotation = null;
        }
    }

    /** Estimate poses [k0, k0 + m) paired with the reference interpolated at their stamps (filled by the caller). */
    static AssociatedColumns interpolated(Trajectory ref, Trajectory est, InterpolatedReference interpolated, int k0,
            int m, double off) {
        return new AssociatedColumns(ref, est, interpolated, null, null, k0, m, off);
    }

    /** Pairs (reference refIndex[k], estimate estIndex[k]) for k &lt; m. */
    static AssociatedColumns matched(Trajectory ref, Trajectory est, int[] refIndex, int[] estIndex, int m,
            double off) {
        return new AssociatedColumns(ref, est, null, refIndex, estIndex, 0, m, off);
    }

    @Override
    public int size() {
        return m;
    }

    @Override
    public PositionColumns reference() {
        return refPositions;
    }

    @Override
    public PositionColumns estimate() {
        return estPositions;
    }

    @Override
    public void referenceRotation(int k, double[] out, int o) {
        if (interpolated != null) {
            interpolated.rotation(k, out, o);
        } else {
            ref.rotation(refIndex[k], out, o);
        }
    }

    /** As {@link #referenceRotation(int, double[], int)}, into {@code out[0..9)} with this thread's scratch. */
    private void referenceRotation(int k, double[] out, Scratch s) {
        if (interpolated != null) {
            interpolated.rotation(k, out, 0, s.cursor());
        } else {
            ref.rotation(refIndex[k], out, 0);
        }
    }

    @Override
    public void estimateRotation(int k, double[] out, int o) {
        est.rotation(estAt(k), out, o);
    }

    /** @return the time of pair k on the estimate's clock, offset applied (s) */
    double stamp(int k) {
        return est.t(estAt(k)) + off;
    }

    private int estAt(int k) {
        return estIndex == null ? k0 + k : estIndex[k];
    }

    /** Sets the alignment applied to the estimate before the errors (identity for model NONE). */
    void align(AlignmentTransform tf) {
        aligned = tf.model() != AlignmentModel.NONE;
        double[] a = tf.rotation();
        a00 = a[0];
        a01 = a[1];
        a02 = a[2];
        a10 = a[3];
        a11 = a[4];
        a12 = a[5];
        a20 = a[6];
        a21 = a[7];
        a22 = a[8];
        double[] t = tf.translation();
        t0 = t[0];
        t1 = t[1];
        t2 = t[2];
        scale = tf.scale();
        planar = PlanarErrors.of(est, estIndex, k0, interpolated, ref, refIndex, tf);
    }

    /**
     * Sets the alignment as {@link #align} does but keeps the 3x3 matrix kernels for planar pairs
     * too: the reference the planar kernels are tested against.
     */
    void alignForMatrixKernels(AlignmentTransform tf) {
        align(tf);
        planar = null;
    }

    /** @return true when the errors are computed from 2x2 rotation blocks ({@link PlanarErrors}) */
    boolean planarKernels() {
        return planar != null;
    }

    /**
     * Per-thread scratch space of the error kernels: the array the trajectories and the
     * interpolated reference write a rotation matrix into (every value derived from it is a local).
     */
    static final class Scratch {
        final double[] ri = new double[9];
        /** Translation error of the last pose or pair computed (m). */
        double transError;
        /** Rotation error of the last pose or pair computed (rad). */
        double rotError;
        private PlanarErrors.Window window;

        /** @return the (cos, sin) window of the planar kernels, made on first use */
        PlanarErrors.Window window() {
            if (window == null) {
                window = new PlanarErrors.Window();
            }
            return window;
        }

        private InterpolatedReference.Cursor cursor;

        /** @return the scratch and cache of an interpolated reference's rotations (made on first use) */
        InterpolatedReference.Cursor cursor() {
            if (cursor == null) {
                cursor = new InterpolatedReference.Cursor();
            }
            return cursor;
        }
    }

    /**
     * The ATE of pair k into {@code s.transError}, |p'_k - p_ref,k| (m), and {@code s.rotError},
     * the angle of R'_k^T R_ref,k (rad).
     */
    void ate(int k, Scratch s) {
        if (planar != null && planar.ate(k, s)) {
            return;
        }
        int e = estAt(k);
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
        referenceRotation(k, m, s);
        s.rotError = angleOfTransposeTimes(e00, e01, e02, e10, e11, e12, e20, e21, e22, m[0], m[1], m[2], m[3], m[4],
                m[5], m[6], m[7], m[8]);
    }

    /**
     * The RPE of pair (i, j): E = (Q_i^-1 Q_j)^-1 (P'_i^-1 P'_j) with inv(A) B = [R_A^T R_B,
     * R_A^T t_B + (-(R_A^T t_A))] (evo's order, {@link RelativeMotion#inverseTimes}); |trans(E)| (m)
     * into {@code s.transError}, its angle (rad) into {@code s.rotError}. For an SE(3) interpolated
     * reference, also the ATE rotation error of pose i from the rotations in hand.
     */
    void rpe(int i, int j, Scratch s) {
        if (planar != null && planar.rpe(i, j, s)) {
            return;
        }
        double[] m = s.ri;
        referenceRotation(i, m, s);
        final double f00 = m[0];
        final double f01 = m[1];
        final double f02 = m[2];
        final double f10 = m[3];
        final double f11 = m[4];
        final double f12 = m[5];
        final double f20 = m[6];
        final double f21 = m[7];
        final double f22 = m[8];
        referenceRotation(j, m, s);
        double g00 = m[0];
        double g01 = m[1];
        double g02 = m[2];
        double g10 = m[3];
        double g11 = m[4];
        double g12 = m[5];
        double g20 = m[6];
        double g21 = m[7];
        double g22 = m[8];
        // Q = inv(Ref_i) Ref_j
        double tx = refPositions.x(i);
        double ty = refPositions.y(i);
        double tz = refPositions.z(i);
        double ux = refPositions.x(j);
        double uy = refPositions.y(j);
        double uz = refPositions.z(j);
        final double q00 = dot(f00, f10, f20, g00, g10, g20);
        final double q01 = dot(f00, f10, f20, g01, g11, g21);
        final double q02 = dot(f00, f10, f20, g02, g12, g22);
        final double q10 = dot(f01, f11, f21, g00, g10, g20);
        final double q11 = dot(f01, f11, f21, g01, g11, g21);
        final double q12 = dot(f01, f11, f21, g02, g12, g22);
        final double q20 = dot(f02, f12, f22, g00, g10, g20);
        final double q21 = dot(f02, f12, f22, g01, g11, g21);
        final double q22 = dot(f02, f12, f22, g02, g12, g22);
        final double qx = dot(f00, f10, f20, ux, uy, uz) + -dot(f00, f10, f20, tx, ty, tz);
        final double qy = dot(f01, f11, f21, ux, uy, uz) + -dot(f01, f11, f21, tx, ty, tz);
        final double qz = dot(f02, f12, f22, ux, uy, uz) + -dot(f02, f12, f22, tx, ty, tz);
        // aligned estimate poses i (rotation b, position t) and j (rotation g, position u)
        int ei = estAt(i);
        int ej = estAt(j);
        est.rotation(ei, m, 0);
        double b00 = m[0];
        double b01 = m[1];
        double b02 = m[2];
        double b10 = m[3];
        double b11 = m[4];
        double b12 = m[5];
        double b20 = m[6];
        double b21 = m[7];
        double b22 = m[8];
        est.rotation(ej, m, 0);
        g00 = m[0];
        g01 = m[1];
        g02 = m[2];
        g10 = m[3];
        g11 = m[4];
        g12 = m[5];
        g20 = m[6];
        g21 = m[7];
        g22 = m[8];
        tx = est.x(ei);
        ty = est.y(ei);
        tz = est.z(ei);
        ux = est.x(ej);
        uy = est.y(ej);
        uz = est.z(ej);
        if (aligned) { // p' = A (s p) + t, R' = A R_est
            double sx = scale * tx;
            double sy = scale * ty;
            double sz = scale * tz;
            tx = dot(a00, a01, a02, sx, sy, sz) + t0;
            ty = dot(a10, a11, a12, sx, sy, sz) + t1;
            tz = dot(a20, a21, a22, sx, sy, sz) + t2;
            sx = scale * ux;
            sy = scale * uy;
            sz = scale * uz;
            ux = dot(a00, a01, a02, sx, sy, sz) + t0;
            uy = dot(a10, a11, a12, sx, sy, sz) + t1;
            uz = dot(a20, a21, a22, sx, sy, sz) + t2;
            double n00 = dot(a00, a01, a02, b00, b10, b20);
            double n01 = dot(a00, a01, a02, b01, b11, b21);
            double n02 = dot(a00, a01, a02, b02, b12, b22);
            double n10 = dot(a10, a11, a12, b00, b10, b20);
            double n11 = dot(a10, a11, a12, b01, b11, b21);
            double n12 = dot(a10, a11, a12, b02, b12, b22);
            double n20 = dot(a20, a21, a22, b00, b10, b20);
            double n21 = dot(a20, a21, a22, b01, b11, b21);
            double n22 = dot(a20, a21, a22, b02, b12, b22);
            b00 = n00;
            b01 = n01;
            b02 = n02;
            b10 = n10;
            b11 = n11;
            b12 = n12;
            b20 = n20;
            b21 = n21;
            b22 = n22;
            n00 = dot(a00, a01, a02, g00, g10, g20);
            n01 = dot(a00, a01, a02, g01, g11, g21);
            n02 = dot(a00, a01, a02, g02, g12, g22);
            n10 = dot(a10, a11, a12, g00, g10, g20);
            n11 = dot(a10, a11, a12, g01, g11, g21);
            n12 = dot(a10, a11, a12, g02, g12, g22);
            n20 = dot(a20, a21, a22, g00, g10, g20);
            n21 = dot(a20, a21, a22, g01, g11, g21);
            n22 = dot(a20, a21, a22, g02, g12, g22);
            g00 = n00;
            g01 = n01;
            g02 = n02;
            g10 = n10;
            g11 = n11;
            g12 = n12;
            g20 = n20;
            g21 = n21;
            g22 = n22;
        }
        if (ateRotation != null) {
            // the ATE rotation error of pose i: the angle of R'_i^T R_ref,i, both in hand
            ateRotation[i] = angleOfTransposeTimes(b00, b01, b02, b10, b11, b12, b20, b21, b22, f00, f01, f02, f10,
                    f11, f12, f20, f21, f22);
        }
        // P = inv(P'_i) P'_j
        double p00 = dot(b00, b10, b20, g00, g10, g20);
        double p01 = dot(b00, b10, b20, g01, g11, g21);
        double p02 = dot(b00, b10, b20, g02, g12, g22);
        double p10 = dot(b01, b11, b21, g00, g10, g20);
        double p11 = dot(b01, b11, b21, g01, g11, g21);
        double p12 = dot(b01, b11, b21, g02, g12, g22);
        double p20 = dot(b02, b12, b22, g00, g10, g20);
        double p21 = dot(b02, b12, b22, g01, g11, g21);
        double p22 = dot(b02, b12, b22, g02, g12, g22);
        double px = dot(b00, b10, b20, ux, uy, uz) + -dot(b00, b10, b20, tx, ty, tz);
        double py = dot(b01, b11, b21, ux, uy, uz) + -dot(b01, b11, b21, tx, ty, tz);
        double pz = dot(b02, b12, b22, ux, uy, uz) + -dot(b02, b12, b22, tx, ty, tz);
        // E = inv(Q) P
        double ex = dot(q00, q10, q20, px, py, pz) + -dot(q00, q10, q20, qx, qy, qz);
        double ey = dot(q01, q11, q21, px, py, pz) + -dot(q01, q11, q21, qx, qy, qz);
        double ez = dot(q02, q12, q22, px, py, pz) + -dot(q02, q12, q22, qx, qy, qz);
        s.transError = Math.sqrt(ex * ex + ey * ey + ez * ez);
        s.rotError = angleOfTransposeTimes(q00, q01, q02, q10, q11, q12, q20, q21, q22, p00, p01, p02, p10, p11, p12,
                p20, p21, p22);
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

    /** @return the length of the associated reference path from pose k to k + 1 (m) */
    double hop(int k) {
        double dx = refPositions.x(k) - refPositions.x(k + 1);
        double dy = refPositions.y(k) - refPositions.y(k + 1);
        double dz = refPositions.z(k) - refPositions.z(k + 1);
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** Positions of a trajectory through an index map (or an offset when the map is null). */
    private static final class Mapped implements PositionColumns {
        private final Trajectory t;
        private final int[] index;
        private final int offset;

        Mapped(Trajectory t, int[] index, int offset) {
            this.t = t;
            this.index = index;
            this.offset = offset;
        }

        private int at(int k) {
            return index == null ? offset + k : index[k];
        }

        @Override
        public double x(int k) {
            return t.x(at(k));
        }

        @Override
        public double y(int k) {
            return t.y(at(k));
        }

        @Override
        public double z(int k) {
            return t.z(at(k));
        }
    }
}
