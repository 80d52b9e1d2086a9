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
    private final double[] rot = new double[9];
    private final double[] trans = new double[3];
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
        System.arraycopy(tf.rotation(), 0, rot, 0, 9);
        System.arraycopy(tf.translation(), 0, trans, 0, 3);
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

    /** Per-thread scratch space of the error kernels. */
    static final class Scratch {
        final double[] ri = new double[9];
        final double[] rj = new double[9];
        final double[] rp = new double[9];
        final double[] pi = new double[3];
        final double[] pj = new double[3];
        final double[] q = new double[12];
        final double[] p = new double[12];
        final double[] e = new double[12];
        final double[] a = new double[9];
        /** Scratch of {@link Rotations#angle(double[], int, double[])}. */
        final double[] quat = new double[4];
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

    /** Writes the aligned estimate pose k: position into {@code p[0..3)} (m), rotation into {@code r} (9). */
    private void alignedPose(int k, double[] p, double[] r, double[] rp) {
        int i = estAt(k);
        alignedPosition(i, p);
        if (!aligned) {
            est.rotation(i, r, 0);
            return;
        }
        double[] mr = rot;
        est.rotation(i, rp, 0);
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 3; col++) {
                r[3 * row + col] = mr[3 * row] * rp[col] + mr[3 * row + 1] * rp[3 + col] + mr[3 * row + 2] * rp[6 + col];
            }
        }
    }

    /** Writes the aligned position of estimate pose i (its own index) into {@code p[0..3)} (m). */
    private void alignedPosition(int i, double[] p) {
        if (!aligned) {
            p[0] = est.x(i);
            p[1] = est.y(i);
            p[2] = est.z(i);
            return;
        }
        double px = scale * est.x(i);
        double py = scale * est.y(i);
        double pz = scale * est.z(i);
        double[] mr = rot;
        p[0] = mr[0] * px + mr[1] * py + mr[2] * pz + trans[0];
        p[1] = mr[3] * px + mr[4] * py + mr[5] * pz + trans[1];
        p[2] = mr[6] * px + mr[7] * py + mr[8] * pz + trans[2];
    }

    /**
     * The ATE of pair k into {@code s.transError}, |p'_k - p_ref,k| (m), and {@code s.rotError},
     * the angle of R'_k^T R_ref,k (rad).
     */
    void ate(int k, Scratch s) {
        if (planar != null && planar.ate(k, s)) {
            return;
        }
        double[] p = s.pi;
        double known = ateRotation == null ? Double.NaN : ateRotation[k];
        if (Double.isNaN(known)) {
            alignedPose(k, p, s.ri, s.rp);
        } else {
            alignedPosition(estAt(k), p);
        }
        double dx = p[0] - refPositions.x(k);
        double dy = p[1] - refPositions.y(k);
        double dz = p[2] - refPositions.z(k);
        s.transError = Math.sqrt(dx * dx + dy * dy + dz * dz);
        s.rotError = Double.isNaN(known) ? rotationError(k, s.ri, s) : known;
    }

    /** @return the angle of R'^T R_ref,k (rad), R' at {@code re}: the ATE's rotation error of pair k */
    private double rotationError(int k, double[] re, Scratch s) {
        referenceRotation(k, s.rj, s);
        double[] rr = s.rj;
        double[] e = s.a;
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                e[3 * r + c] = re[r] * rr[c] + re[3 + r] * rr[3 + c] + re[6 + r] * rr[6 + c];
            }
        }
        return Rotations.angle(e, 0, s.quat);
    }

    /**
     * The RPE of pair (i, j): E = (Q_i^-1 Q_j)^-1 (P'_i^-1 P'_j) into {@code s.e} (R: e[0..9),
     * t: e[9..12)), |trans(E)| (m) into {@code s.transError}, its angle (rad) into {@code s.rotError}.
     */
    void rpe(int i, int j, Scratch s) {
        if (planar != null && planar.rpe(i, j, s)) {
            return;
        }
        referenceRotation(i, s.ri, s);
        referenceRotation(j, s.rj, s);
        RelativeMotion.inverseTimes(s.ri, refPositions.x(i), refPositions.y(i), refPositions.z(i), s.rj,
                refPositions.x(j), refPositions.y(j), refPositions.z(j), s.q);
        alignedPose(i, s.pi, s.ri, s.rp);
        alignedPose(j, s.pj, s.rj, s.rp);
        RelativeMotion.inverseTimes(s.ri, s.pi[0], s.pi[1], s.pi[2], s.rj, s.pj[0], s.pj[1], s.pj[2], s.p);
        double[] q = s.q;
        double[] p = s.p;
        double[] e = s.e;
        RelativeMotion.inverseTimes(q, q[9], q[10], q[11], p, p[9], p[10], p[11], e);
        s.transError = Math.sqrt(e[9] * e[9] + e[10] * e[10] + e[11] * e[11]);
        s.rotError = Rotations.angle(e, 0, s.quat);
        if (ateRotation != null) {
            // s.ri holds R'_i; the reference rotation of i is still in the thread's cache
            ateRotation[i] = rotationError(i, s.ri, s);
        }
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
