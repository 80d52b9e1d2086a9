package org.trajeval.core.assoc;

import java.util.Arrays;
import java.util.function.IntToDoubleFunction;
import org.trajeval.core.geom.Rotations;
import org.trajeval.core.geom.Slerp;
import org.trajeval.core.geom.StrictAtan2;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.PoseSequence;
import org.trajeval.core.traj.PositionColumns;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * A reference interpolated at increasing query stamps, held column-wise. Planar data: positions
 * (m) and the yaw (rad), 24 B per pose. SE(3) data: only the bracket, i.e. the segment index and
 * the fraction f (12 B per pose instead of 56 B for positions and the slerped quaternion);
 * positions and rotations are computed on demand from the reference's own columns by the same
 * expressions as when they were stored, so every value is bit for bit the stored one. Rotation
 * matrices are derived on demand in both cases. Two rules:
 * <ul>
 * <li>planar (the lesson's): segment = first reference pose with t &gt;= query in [1, n-1],
 *     f = (t - t_prev) / (t_next - t_prev) clamped to [0, 1], x, y linear, yaw through its sine
 *     and cosine (yaw = atan2(s_prev + f (s_next - s_prev), c_prev + f (c_next - c_prev))),
 *     continuous across the +-pi cut;</li>
 * <li>spatial (evo's {@code PoseTrajectory3D.interpolate}): the same segment and fraction
 *     (f = 0 for a zero-length segment), positions linear, rotation by slerp of the quaternions
 *     along the shorter arc. Queries outside the span are clamped to the end poses.</li>
 * </ul>
 * Filled chunk by chunk ({@link #fill}): each chunk finds its first segment by binary search, so
 * chunks are independent and the result does not depend on how the range is cut. An SE(3)
 * rotation costs a slerp and a quaternion-to-matrix conversion; a {@link Cursor} (one per thread)
 * keeps the last {@value Cursor#SLOTS} matrices computed, so a pose met again within that many
 * poses is not recomputed (a caller that keeps the matrices itself, as the RPE's pose window does, takes
 * them uncached from {@link #rotationOnce} or two side by side from {@link #rotationsOnce}), and the {@link Slerp}
 * of the last segment, so that poses asked in increasing order normalise each reference
 * quaternion once and poses on one segment share its arc (about 110 ns per rotation on the
 * benchmark machine, most of it the three sines and the arc cosine that give evo's bits).
 */
public final class InterpolatedReference implements PositionColumns {
    private final PlanarTrajectory planarRef;
    private final SpatialTrajectory spatialRef;
    private final double[] x;
    private final double[] y;
    private final double[] yaw;
    /** SE(3): the segment of pose k is reference poses (seg[k] - 1, seg[k]). */
    private final int[] seg;
    /** SE(3): the fraction of pose k along its segment, in [0, 1]. */
    private final double[] frac;
    private final int n;

    private InterpolatedReference(PlanarTrajectory planarRef, SpatialTrajectory spatialRef, int n) {
        this.planarRef = planarRef;
        this.spatialRef = spatialRef;
        this.n = n;
        boolean planar = planarRef != null;
        this.x = planar ? new double[n] : null;
        this.y = planar ? new double[n] : null;
        this.yaw = planar ? new double[n] : null;
        this.seg = planar ? null : new int[n];
        this.frac = planar ? null : new double[n];
    }

    /** @return room for n poses of a planar reference, interpolated by the lesson's rule */
    public static InterpolatedReference planar(PlanarTrajectory ref, int n) {
        return new InterpolatedReference(ref, null, n);
    }

    /** @return room for n poses of an SE(3) reference, interpolated by evo's rule */
    public static InterpolatedReference spatial(SpatialTrajectory ref, int n) {
        return new InterpolatedReference(null, ref, n);
    }

    /** @return the reference interpolated at every stamp (increasing, s) */
    static PoseSequence planarAt(PlanarTrajectory ref, double[] stamps) {
        InterpolatedReference r = planar(ref, stamps.length);
        r.fill(k -> stamps[k], 0, stamps.length);
        return r.toPoses();
    }

    /** @return the reference interpolated at every stamp (increasing, s) */
    static PoseSequence spatialAt(SpatialTrajectory ref, double[] stamps) {
        InterpolatedReference r = spatial(ref, stamps.length);
        r.fill(k -> stamps[k], 0, stamps.length);
        return r.toPoses();
    }

    /**
     * Interpolates poses [from, to) at {@code stamp.applyAsDouble(k)} (s, increasing in k).
     * Disjoint ranges may be filled from different threads.
     */
    public void fill(IntToDoubleFunction stamp, int from, int to) {
        if (from >= to) {
            return;
        }
        if (planarRef != null) {
            fillPlanar(stamp, from, to);
        } else {
            fillSpatial(stamp, from, to);
        }
    }

    private void fillPlanar(IntToDoubleFunction stamp, int from, int to) {
        PlanarTrajectory ref = planarRef;
        int last = ref.size() - 1;
        int seg = ref.firstAtOrAfter(stamp.applyAsDouble(from), 1, last); // last when none
        double c0 = Math.cos(ref.yaw(seg - 1));
        double s0 = Math.sin(ref.yaw(seg - 1));
        double c1 = Math.cos(ref.yaw(seg));
        double s1 = Math.sin(ref.yaw(seg));
        for (int k = from; k < to; k++) {
            double t = stamp.applyAsDouble(k);
            while (seg < last && ref.t(seg) < t) {
                seg++;
                c0 = c1;
                s0 = s1;
                c1 = Math.cos(ref.yaw(seg));
                s1 = Math.sin(ref.yaw(seg));
            }
            double ta = ref.t(seg - 1);
            double f = (t - ta) / (ref.t(seg) - ta);
            f = Math.max(0.0, Math.min(1.0, f));
            x[k] = ref.x(seg - 1) + f * (ref.x(seg) - ref.x(seg - 1));
            y[k] = ref.y(seg - 1) + f * (ref.y(seg) - ref.y(seg - 1));
            yaw[k] = StrictAtan2.atan2(s0 + f * (s1 - s0), c0 + f * (c1 - c0)); // Math.atan2's bits
        }
    }

    private void fillSpatial(IntToDoubleFunction stamp, int from, int to) {
        SpatialTrajectory ref = spatialRef;
        int nr = ref.size();
        int idx = ref.firstAtOrAfter(stamp.applyAsDouble(from), 0, nr);
        for (int k = from; k < to; k++) {
            double t = stamp.applyAsDouble(k);
            while (idx < nr && ref.t(idx) < t) {
                idx++;
            }
            int s = Math.max(1, Math.min(nr - 1, idx));
            double tPrev = ref.t(s - 1);
            double dt = ref.t(s) - tPrev;
            double f = dt > 0.0 ? (t - tPrev) / dt : 0.0;
            seg[k] = s;
            frac[k] = Math.max(0.0, Math.min(1.0, f));
        }
    }

    /** @return number of poses */
    public int size() {
        return n;
    }

    /** @return true for an SE(3) reference (rotations computed on demand by a slerp), false for planar data */
    public boolean isSpatial() {
        return spatialRef != null;
    }

    // positions of SE(3) data: a + f (b - a) of the segment's end poses, the expression of evo's
    // linear interpolation (and of this class when it stored them)

    @Override
    public double x(int k) {
        if (x != null) {
            return x[k];
        }
        int s = seg[k];
        return spatialRef.x(s - 1) + frac[k] * (spatialRef.x(s) - spatialRef.x(s - 1));
    }

    @Override
    public double y(int k) {
        if (y != null) {
            return y[k];
        }
        int s = seg[k];
        return spatialRef.y(s - 1) + frac[k] * (spatialRef.y(s) - spatialRef.y(s - 1));
    }

    @Override
    public double z(int k) {
        if (x != null) {
            return 0.0;
        }
        int s = seg[k];
        return spatialRef.z(s - 1) + frac[k] * (spatialRef.z(s) - spatialRef.z(s - 1));
    }

    /** @return the interpolated yaw of pose k (rad); planar references only */
    public double yaw(int k) {
        return yaw[k];
    }

    /** @return true when the reference is planar (rotations about +z by {@link #yaw}) */
    public boolean isPlanar() {
        return yaw != null;
    }

    /** Writes the rotation matrix of pose k (row-major) into {@code out[o..o+9)} (allocates a cursor for SE(3)). */
    public void rotation(int k, double[] out, int o) {
        if (yaw != null) {
            Rotations.aboutZ(yaw[k], out, o);
        } else {
            rotation(k, out, o, new Cursor());
        }
    }

    /**
     * Writes the rotation matrix of pose k (row-major) into {@code out[o..o+9)}: planar data
     * {@link Rotations#aboutZ} of the yaw, SE(3) data {@link Rotations#fromQuaternion} of the
     * slerp of the segment's quaternions, taken from the cursor's cache when it holds pose k.
     *
     * @param cursor this thread's scratch and cache (unused for planar data)
     */
    public void rotation(int k, double[] out, int o, Cursor cursor) {
        if (yaw != null) {
            Rotations.aboutZ(yaw[k], out, o);
            return;
        }
        int slot = k & (Cursor.SLOTS - 1);
        double[] cached = cursor.matrices;
        int c = 9 * slot;
        if (cursor.owner != this) {
            cursor.clear(this);
        } else if (cursor.pose[slot] == k) {
            copy9(cached, c, out, o);
            return;
        }
        slerped(k, cursor, cached, c);
        cursor.pose[slot] = k;
        copy9(cached, c, out, o);
    }

    /**
     * Writes the rotation matrix of pose k into {@code out[o..o+9)} as {@link #rotation(int, double[],
     * int, Cursor)} does, without the cursor's matrix cache (neither read nor filled; its slerp is
     * used): for callers that keep the matrix themselves, so it is neither looked up nor copied twice.
     */
    public void rotationOnce(int k, double[] out, int o, Cursor cursor) {
        if (yaw != null) {
            Rotations.aboutZ(yaw[k], out, o);
            return;
        }
        if (cursor.owner != this) {
            cursor.clear(this);
        }
        slerped(k, cursor, out, o);
    }

    /**
     * {@link #rotationOnce} of poses k and k + 1 into {@code out[o..o+9)} and {@code out[p..p+9)}, the
     * two slerps side by side ({@link Slerp#atBoth}): the same values, with their long chains overlapped.
     */
    public void rotationsOnce(int k, double[] out, int o, int p, Cursor cursor) {
        if (yaw != null) {
            Rotations.aboutZ(yaw[k], out, o);
            Rotations.aboutZ(yaw[k + 1], out, p);
            return;
        }
        if (cursor.owner != this) {
            cursor.clear(this);
        }
        int s = seg[k + 1];
        double[] q = cursor.q;
        double[] q1 = cursor.q1;
        Slerp first = toSegment(seg[k], cursor);
        Slerp second = first;
        if (s != cursor.segment) {
            second = cursor.spare;
            if (s == cursor.segment + 1) {
                spatialRef.quaternion(s, q1);
                second.follow(first, q1[0], q1[1], q1[2], q1[3]);
            } else {
                double[] q0 = cursor.q0;
                spatialRef.quaternion(s - 1, q0);
                spatialRef.quaternion(s, q1);
                second.ends(q0[0], q0[1], q0[2], q0[3], q1[0], q1[1], q1[2], q1[3]);
            }
            cursor.spare = first;
            cursor.slerp = second;
            cursor.segment = s;
        }
        Slerp.atBoth(first, frac[k], q, 0, second, frac[k + 1], q1, 0);
        Rotations.fromQuaternion(q[0], q[1], q[2], q[3], out, o);
        Rotations.fromQuaternion(q1[0], q1[1], q1[2], q1[3], out, p);
    }

    /** Copies 9 doubles (inline: a 9-element System.arraycopy is a call to a stub). */
    private static void copy9(double[] from, int f, double[] to, int t) {
        for (int i = 0; i < 9; i++) {
            to[t + i] = from[f + i];
        }
    }

    /**
     * The matrix of the slerp of pose k's segment quaternions into {@code out[o..o+9)}; the
     * cursor's {@link Slerp} keeps the segment it was last set to, and moves on to the next one
     * keeping the shared end.
     */
    private void slerped(int k, Cursor cursor, double[] out, int o) {
        double[] q = cursor.q;
        toSegment(seg[k], cursor).at(frac[k], q, 0);
        Rotations.fromQuaternion(q[0], q[1], q[2], q[3], out, o);
    }

    /** @return the cursor's {@link Slerp}, set to segment s (advanced when s follows its segment) */
    private Slerp toSegment(int s, Cursor cursor) {
        Slerp slerp = cursor.slerp;
        double[] q = cursor.q;
        if (s != cursor.segment) {
            if (s == cursor.segment + 1) {
                spatialRef.quaternion(s, q);
                slerp.advance(q[0], q[1], q[2], q[3]);
            } else {
                double[] q0 = cursor.q0;
                spatialRef.quaternion(s - 1, q0);
                spatialRef.quaternion(s, q);
                slerp.ends(q0[0], q0[1], q0[2], q0[3], q[0], q[1], q[2], q[3]);
            }
            cursor.segment = s;
        }
        return slerp;
    }

    /** @return the poses as a materialised sequence (rotation matrices, z = 0 for planar data) */
    public PoseSequence toPoses() {
        double[] px = new double[n];
        double[] py = new double[n];
        double[] pz = new double[n];
        double[] r = new double[9 * n];
        Cursor cursor = new Cursor();
        for (int k = 0; k < n; k++) {
            px[k] = x(k);
            py[k] = y(k);
            pz[k] = z(k);
            rotation(k, r, 9 * k, cursor);
        }
        return PoseSequence.of(px, py, pz, r);
    }

    /**
     * One thread's scratch for {@link #rotation(int, double[], int, Cursor)}: the slerp of the last
     * segment met and a direct-mapped cache of the last SE(3) rotation matrices it computed (pose k
     * in slot k mod {@value #SLOTS}; 74 KB). Bound to one reference at a time: used with another,
     * it forgets what it held.
     */
    public static final class Cursor {
        /** Number of cached matrices (a power of two). */
        public static final int SLOTS = 1024;
        private final double[] q0 = new double[4];
        private final double[] q = new double[4];
        private final double[] q1 = new double[4];
        private final double[] matrices = new double[9 * SLOTS];
        private final int[] pose = new int[SLOTS];
        private Slerp slerp = new Slerp();
        /** A second slerp, for the next segment of {@link #rotationsOnce}; the two swap roles. */
        private Slerp spare = new Slerp();
        /** The segment {@link #slerp} is set to (-1: none). */
        private int segment = -1;
        private InterpolatedReference owner;

        private void clear(InterpolatedReference reference) {
            Arrays.fill(pose, -1);
            segment = -1;
            owner = reference;
        }
    }
}
