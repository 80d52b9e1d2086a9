package org.trajeval.core.eval;

import java.util.Arrays;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.align.PosePairs;
import org.trajeval.core.assoc.InterpolatedReference;
import org.trajeval.core.traj.PlanarTrajectory;
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
 * same bits); the 3x3 kernels ({@link SpatialErrors}) compute them for SE(3) pairs and as its fallback.
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
     * ATE rotation errors (rad) computed by {@link #rpe} for its start pose i while the rotations of i
     * are in the thread's window, NaN where not yet computed; for SE(3) pairs only (8 B per pose
     * against a second slerp for an interpolated reference, or against a second pass that converts
     * both quaternions of every pose to matrices again for matched pairs).
     */
    private final double[] ateRotation;
    /** The 3x3 kernels for the alignment set last. */
    private SpatialErrors spatial;
    /** The 2x2 kernels when the pairs and the alignment are planar; null otherwise. */
    private PlanarErrors planar;
    /** Where the 2x2 kernels keep their ATE rotations (at least m values), null to allocate. */
    private double[] planarRotationStore;

    private AssociatedColumns(Trajectory ref, Trajectory est, InterpolatedReference interpolated, int[] refIndex,
            int[] estIndex, int k0, int m, double off, Parallelism fill) {
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
        boolean spatial = interpolated != null ? interpolated.isSpatial() : !(ref instanceof PlanarTrajectory);
        if (spatial) {
            double[] known = new double[m];
            fill.forEachChunk(m, (c, from, to) -> Arrays.fill(known, from, to, Double.NaN));
            this.ateRotation = known;
        } else {
            this.ateRotation = null;
        }
    }

    /** Estimate poses [k0, k0 + m) paired with the reference interpolated at their stamps (filled by the caller). */
    static AssociatedColumns interpolated(Trajectory ref, Trajectory est, InterpolatedReference interpolated, int k0,
            int m, double off) {
        return new AssociatedColumns(ref, est, interpolated, null, null, k0, m, off, Parallelism.SEQUENTIAL);
    }

    /**
     * Pairs (reference refIndex[k], estimate estIndex[k]) for k &lt; m; the ATE rotation cache of SE(3)
     * pairs is set up (first touched) on the threads of {@code par}.
     */
    static AssociatedColumns matched(Trajectory ref, Trajectory est, int[] refIndex, int[] estIndex, int m,
            double off, Parallelism par) {
        return new AssociatedColumns(ref, est, null, refIndex, estIndex, 0, m, off, par);
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

    /** As {@link #referenceRotation(int, double[], int)}, with this thread's scratch (and cache). */
    void referenceRotation(int k, double[] out, int o, Scratch s) {
        if (interpolated != null) {
            interpolated.rotation(k, out, o, s.cursor());
        } else {
            ref.rotation(refIndex[k], out, o);
        }
    }

    /**
     * As {@link #referenceRotation(int, double[], int, Scratch)}, for a caller that keeps the matrix
     * (the window of {@link SpatialErrors}): an interpolated rotation skips the cursor's matrix cache.
     */
    void referenceRotationOnce(int k, double[] out, int o, Scratch s) {
        if (interpolated != null) {
            interpolated.rotationOnce(k, out, o, s.cursor());
        } else {
            ref.rotation(refIndex[k], out, o);
        }
    }

    /** {@link #referenceRotationOnce} of pairs k and k + 1 into {@code out[o..o+9)} and {@code out[p..p+9)}. */
    void referenceRotationsOnce(int k, double[] out, int o, int p, Scratch s) {
        if (interpolated != null) {
            interpolated.rotationsOnce(k, out, o, p, s.cursor());
        } else {
            ref.rotation(refIndex[k], out, o);
            ref.rotation(refIndex[k + 1], out, p);
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

    /** @return the estimate's own index of pair k */
    int estimateIndex(int k) {
        return estAt(k);
    }

    private int estAt(int k) {
        return estIndex == null ? k0 + k : estIndex[k];
    }

    /** @return true when the RPE pass left the ATE rotation error of pose k (it is not computed again) */
    boolean ateRotationKnown(int k) {
        return ateRotation != null && !Double.isNaN(ateRotation[k]);
    }

    /**
     * The 2x2 kernels set by the next {@link #align} keep the ATE rotations the RPE computes in
     * {@code store} (at least m values, overwritten) instead of an array of their own.
     */
    void keepPlanarRotationsIn(double[] store) {
        planarRotationStore = store;
    }

    /** Sets the alignment applied to the estimate before the errors (identity for model NONE). */
    void align(AlignmentTransform tf) {
        spatial = new SpatialErrors(this, est, ateRotation, tf);
        planar = PlanarErrors.of(est, estIndex, k0, interpolated, ref, refIndex, tf, m, planarRotationStore);
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
        /** The two angles of {@link org.trajeval.core.geom.Rotations#angles}. */
        final double[] angles = new double[2];
        /** Translation error of the last pose or pair computed (m). */
        double transError;
        /** Rotation error of the last pose or pair computed (rad). */
        double rotError;
        /**
         * True when nearly every pose index is asked, in increasing runs (every start pose, or stride 1):
         * the 3x3 kernels' window then computes a missing pose together with the next one.
         */
        boolean posesInRuns;
        private PlanarErrors.Window window;
        private SpatialErrors.Window spatialWindow;

        /** @return the pose window of the 3x3 kernels, made on first use */
        SpatialErrors.Window spatialWindow() {
            if (spatialWindow == null) {
                spatialWindow = new SpatialErrors.Window();
            }
            return spatialWindow;
        }

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
        if (planar == null || !planar.ate(k, s)) {
            spatial.ate(k, s);
        }
    }

    /** The ATE of pairs [from, to) into {@code trans[k]} (m) and {@code rot[k]} (rad), as {@link #ate} gives them. */
    void ateInto(int from, int to, double[] trans, double[] rot, Scratch s) {
        if (planar == null) {
            spatial.ateInto(from, to, trans, rot, s);
            return;
        }
        for (int k = from; k < to; k++) {
            ate(k, s);
            trans[k] = s.transError;
            rot[k] = s.rotError;
        }
    }

    /**
     * The RPE of pair (i, j): E = (Q_i^-1 Q_j)^-1 (P'_i^-1 P'_j), |trans(E)| (m) into
     * {@code s.transError}, its angle (rad) into {@code s.rotError}.
     */
    void rpe(int i, int j, Scratch s) {
        if (planar == null || !planar.rpe(i, j, s)) {
            spatial.rpe(i, j, s);
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
