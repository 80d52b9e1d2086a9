package org.trajeval.core.eval;

import java.util.Arrays;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.assoc.InterpolatedReference;
import org.trajeval.core.geom.PlanarAngle;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * The ATE and RPE kernels of {@link AssociatedColumns} for planar pairs (both trajectories
 * planar, the alignment a rotation about +z with no z translation): every rotation is a 2x2
 * block [[c, -s], [s, c]] of (cos yaw, sin yaw) and every position (x, y), and the errors are
 * computed by the matrix kernels' floating-point operations in their order, with the operations on
 * the structural zeros and ones of the 3x3 matrices (third row and column, z) left out.
 *
 * <p>Bit identity: such an operation adds a signed zero or multiplies one by a finite value, so it
 * changes no nonzero value, and the sign of a zero is lost in the squares and in
 * {@link PlanarAngle}. The one exception is a product 0 * inf of the matrix path (coordinates that
 * overflow): a translation error that is not finite is therefore recomputed by the matrix kernel
 * (the caller's fallback), and so is a rotation block that is not orthogonal ({@link PlanarAngle}).
 * The general path treats the estimate as aligned by the identity when the model is none; 1 x = x
 * and 0 y + x = x up to the sign of a zero, so the aligned form serves both.
 *
 * <p>Each (cos, sin) of a yaw costs two library calls; an RPE pair touches two poses and the ATE
 * one. {@link Window} keeps those of the poses a thread met last (a ring over pose indices,
 * 32 B per slot, chunk-local), so the RPE computes them once per pose when pairs move forward.
 * The RPE of a pair (i, j) also computes the ATE rotation error of its start pose i, whose
 * (cos, sin) and aligned rotation it has at hand, side by side with its own angle
 * ({@link PlanarAngle#two}), and keeps it (8 B per pose, NaN until computed), so the ATE pass that
 * follows the RPE takes no (cos, sin) and no angle for those poses: the same operations on the same
 * values, so the same bits.
 */
final class PlanarErrors {
    private final PlanarTrajectory est;
    private final int[] estIndex;
    private final int k0;
    private final InterpolatedReference interpolated;
    private final PlanarTrajectory ref;
    private final int[] refIndex;
    private final double a00;
    private final double a01;
    private final double a10;
    private final double a11;
    private final double tx;
    private final double ty;
    private final double scale;
    /**
     * ATE rotation errors (rad) of the poses an RPE pair started from, NaN for the others; threads
     * whose pairs share a start pose write the same value.
     */
    private final double[] ateRotation;

    private PlanarErrors(PlanarTrajectory est, int[] estIndex, int k0, InterpolatedReference interpolated,
            PlanarTrajectory ref, int[] refIndex, double[] r, double[] t, double scale, int m, double[] store) {
        this.est = est;
        this.estIndex = estIndex;
        this.k0 = k0;
        this.interpolated = interpolated;
        this.ref = ref;
        this.refIndex = refIndex;
        this.a00 = r[0];
        this.a01 = r[1];
        this.a10 = r[3];
        this.a11 = r[4];
        this.tx = t[0];
        this.ty = t[1];
        this.scale = scale;
        this.ateRotation = store != null ? store : new double[m];
        Arrays.fill(ateRotation, 0, m, Double.NaN);
    }

    /**
     * @return the planar kernels of these pairs, or {@code null} when a trajectory is not planar or
     *     the alignment is not a rotation about +z without z translation (the matrix kernels apply)
     * @param store an array of at least m values that keeps the ATE rotations the RPE computes
     *     (overwritten), or null to allocate one
     */
    static PlanarErrors of(Object est, int[] estIndex, int k0, InterpolatedReference interpolated, Object ref,
            int[] refIndex, AlignmentTransform tf, int m, double[] store) {
        if (!(est instanceof PlanarTrajectory pe) || !(ref instanceof PlanarTrajectory pr)
                || interpolated != null && !interpolated.isPlanar()) {
            return null;
        }
        if (tf.model() == AlignmentModel.NONE) {
            return new PlanarErrors(pe, estIndex, k0, interpolated, pr, refIndex,
                    new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, new double[3], 1.0, m, store);
        }
        double[] r = tf.rotation();
        double[] t = tf.translation();
        boolean aboutZ = r[2] == 0.0 && r[5] == 0.0 && r[6] == 0.0 && r[7] == 0.0 && r[8] == 1.0 && t[2] == 0.0;
        return aboutZ ? new PlanarErrors(pe, estIndex, k0, interpolated, pr, refIndex, r, t, tf.scale(), m, store) : null;
    }

    private int estAt(int k) {
        return estIndex == null ? k0 + k : estIndex[k];
    }

    private double refX(int k) {
        return interpolated != null ? interpolated.x(k) : ref.x(refIndex[k]);
    }

    private double refY(int k) {
        return interpolated != null ? interpolated.y(k) : ref.y(refIndex[k]);
    }

    private double refYaw(int k) {
        return interpolated != null ? interpolated.yaw(k) : ref.yaw(refIndex[k]);
    }

    /** Writes cos, sin of the estimate yaw and cos, sin of the reference yaw of pair k into v[o..o+4). */
    private void trig(int k, double[] v, int o) {
        double ye = est.yaw(estAt(k));
        double yr = refYaw(k);
        v[o] = Math.cos(ye);
        v[o + 1] = Math.sin(ye);
        v[o + 2] = Math.cos(yr);
        v[o + 3] = Math.sin(yr);
    }

    /**
     * The angle (rad) of R'^T R_ref, R' = A R_est, for R_est = [[ce, -se], [se, ce]] and
     * R_ref = [[cr, -sr], [sr, cr]]: the ATE rotation error of a pose.
     */
    private double ateAngle(double ce, double se, double cr, double sr) {
        double r00 = a00 * ce + a01 * se;
        double r01 = a00 * -se + a01 * ce;
        double r10 = a10 * ce + a11 * se;
        double r11 = a10 * -se + a11 * ce;
        // E = R'^T R_ref
        return PlanarAngle.of(r00 * cr + r10 * sr, r00 * -sr + r10 * cr, r01 * cr + r11 * sr, r01 * -sr + r11 * cr);
    }

    /**
     * The ATE of pair k into {@code s.transError} (m) and {@code s.rotError} (rad), as
     * {@link AssociatedColumns#ate}.
     *
     * @return false when the translation error is not finite (the caller recomputes with matrices)
     */
    boolean ate(int k, AssociatedColumns.Scratch s) {
        int e = estAt(k);
        // aligned estimate p' = A (s p) + t, R' = A R_est
        double px = scale * est.x(e);
        double py = scale * est.y(e);
        double dx = a00 * px + a01 * py + tx - refX(k);
        double dy = a10 * px + a11 * py + ty - refY(k);
        double trans = Math.sqrt(dx * dx + dy * dy);
        if (!Double.isFinite(trans)) {
            return false;
        }
        s.transError = trans;
        double known = ateRotation[k];
        if (!Double.isNaN(known)) {
            s.rotError = known;
            return true;
        }
        double ye = est.yaw(e);
        double yr = refYaw(k);
        s.rotError = ateAngle(Math.cos(ye), Math.sin(ye), Math.cos(yr), Math.sin(yr));
        return true;
    }

    /**
     * The RPE of pair (i, j) into {@code s.transError} (m) and {@code s.rotError} (rad), as
     * {@link AssociatedColumns#rpe}: E = (Q_i^-1 Q_j)^-1 (P'_i^-1 P'_j).
     *
     * @return false when the translation error is not finite (the caller recomputes with matrices)
     */
    boolean rpe(int i, int j, AssociatedColumns.Scratch s) {
        Window w = s.window();
        int o = w.slot(this, i);
        double[] v = w.v;
        final double cei = v[o];
        final double sei = v[o + 1];
        final double cri = v[o + 2];
        final double sri = v[o + 3];
        o = w.slot(this, j);
        v = w.v;
        final double cej = v[o];
        final double sej = v[o + 1];
        final double crj = v[o + 2];
        final double srj = v[o + 3];
        // Q = inv(Q_i) Q_j: rotation Ri^T Rj, translation Ri^T tj + (-(Ri^T ti)); Ri = [[cri, -sri], [sri, cri]]
        double rxi = refX(i);
        double ryi = refY(i);
        double rxj = refX(j);
        double ryj = refY(j);
        double q00 = cri * crj + sri * srj;
        double q01 = cri * -srj + sri * crj;
        double q10 = -sri * crj + cri * srj;
        double q11 = -sri * -srj + cri * crj;
        double qi0 = -(cri * rxi + sri * ryi);
        double qi1 = -(-sri * rxi + cri * ryi);
        double qx = cri * rxj + sri * ryj + qi0;
        double qy = -sri * rxj + cri * ryj + qi1;
        // aligned estimate poses i and j: p' = A (s p) + t, R' = A R_est
        int ei = estAt(i);
        int ej = estAt(j);
        double pxi = scale * est.x(ei);
        double pyi = scale * est.y(ei);
        double pxj = scale * est.x(ej);
        double pyj = scale * est.y(ej);
        double xi = a00 * pxi + a01 * pyi + tx;
        double yi = a10 * pxi + a11 * pyi + ty;
        double xj = a00 * pxj + a01 * pyj + tx;
        double yj = a10 * pxj + a11 * pyj + ty;
        double i00 = a00 * cei + a01 * sei;
        double i01 = a00 * -sei + a01 * cei;
        double i10 = a10 * cei + a11 * sei;
        double i11 = a10 * -sei + a11 * cei;
        double j00 = a00 * cej + a01 * sej;
        double j01 = a00 * -sej + a01 * cej;
        double j10 = a10 * cej + a11 * sej;
        double j11 = a10 * -sej + a11 * cej;
        // P = inv(P'_i) P'_j
        double p00 = i00 * j00 + i10 * j10;
        double p01 = i00 * j01 + i10 * j11;
        double p10 = i01 * j00 + i11 * j10;
        double p11 = i01 * j01 + i11 * j11;
        double pi0 = -(i00 * xi + i10 * yi);
        double pi1 = -(i01 * xi + i11 * yi);
        double px = i00 * xj + i10 * yj + pi0;
        double py = i01 * xj + i11 * yj + pi1;
        // E = inv(Q) P
        double ei0 = -(q00 * qx + q10 * qy);
        double ei1 = -(q01 * qx + q11 * qy);
        double ex = q00 * px + q10 * py + ei0;
        double ey = q01 * px + q11 * py + ei1;
        double trans = Math.sqrt(ex * ex + ey * ey);
        if (!Double.isFinite(trans)) {
            return false;
        }
        s.transError = trans;
        // with the ATE rotation error of pose i, the angle of R'_i^T R_ref,i (R'_i = [[i00, i01], [i10, i11]],
        // the block of ateAngle): two angles side by side
        double[] two = s.angles;
        PlanarAngle.two(q00 * p00 + q10 * p10, q00 * p01 + q10 * p11, q01 * p00 + q11 * p10, q01 * p01 + q11 * p11,
                i00 * cri + i10 * sri, i00 * -sri + i10 * cri, i01 * cri + i11 * sri, i01 * -sri + i11 * cri, two, 0);
        s.rotError = two[0];
        ateRotation[i] = two[1];
        return true;
    }

    /**
     * cos and sin of the estimate and reference yaws of the pairs [lo, hi) a thread met last, in a
     * ring indexed by pair mod capacity. Pairs asked for in increasing order are computed once;
     * a pair behind the window (pairs further apart than the capacity) starts the window again
     * and doubles its capacity, up to 2^16 slots (2 MiB).
     */
    static final class Window {
        private static final int MAX_SLOTS = 1 << 16;
        private double[] v = new double[4 * 1024];
        private int mask = 1023;
        private int lo;
        private int hi;

        /** @return the offset in {@code v} of pair k's four values, computing the pairs up to k */
        int slot(PlanarErrors kernel, int k) {
            if (k >= lo && k < hi) {
                return 4 * (k & mask);
            }
            if (k < lo || k - hi > mask) {
                if (k < lo && mask + 1 < MAX_SLOTS) {
                    v = new double[2 * v.length];
                    mask = 2 * mask + 1;
                }
                lo = k;
                hi = k;
            }
            while (hi <= k) {
                kernel.trig(hi, v, 4 * (hi & mask));
                hi++;
            }
            lo = Math.max(lo, hi - mask - 1);
            return 4 * (k & mask);
        }
    }
}
