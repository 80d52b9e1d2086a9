package org.trajeval.core.assoc;

import java.util.function.IntToDoubleFunction;
import org.trajeval.core.geom.Rotations;
import org.trajeval.core.geom.StrictAtan2;
import org.trajeval.core.traj.PlanarTrajectory;
import org.trajeval.core.traj.PoseSequence;
import org.trajeval.core.traj.PositionColumns;
import org.trajeval.core.traj.SpatialTrajectory;

/**
 * A reference interpolated at increasing query stamps, held column-wise: positions (m) and, for
 * planar data, the yaw (rad; 24 B per pose), else the unit quaternion (56 B per pose); rotation
 * matrices are derived on demand. Two rules:
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
 * chunks are independent and the result does not depend on how the range is cut.
 */
public final class InterpolatedReference implements PositionColumns {
    private final PlanarTrajectory planarRef;
    private final SpatialTrajectory spatialRef;
    private final double[] x;
    private final double[] y;
    private final double[] z;
    private final double[] yaw;
    private final double[] q;

    private InterpolatedReference(PlanarTrajectory planarRef, SpatialTrajectory spatialRef, int n) {
        this.planarRef = planarRef;
        this.spatialRef = spatialRef;
        this.x = new double[n];
        this.y = new double[n];
        this.z = planarRef != null ? null : new double[n];
        this.yaw = planarRef != null ? new double[n] : null;
        this.q = planarRef != null ? null : new double[4 * n];
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
        double[] q0 = new double[4];
        double[] q1 = new double[4];
        int idx = ref.firstAtOrAfter(stamp.applyAsDouble(from), 0, nr);
        for (int k = from; k < to; k++) {
            double t = stamp.applyAsDouble(k);
            while (idx < nr && ref.t(idx) < t) {
                idx++;
            }
            int seg = Math.max(1, Math.min(nr - 1, idx));
            double tPrev = ref.t(seg - 1);
            double dt = ref.t(seg) - tPrev;
            double f = dt > 0.0 ? (t - tPrev) / dt : 0.0;
            f = Math.max(0.0, Math.min(1.0, f));
            x[k] = ref.x(seg - 1) + f * (ref.x(seg) - ref.x(seg - 1));
            y[k] = ref.y(seg - 1) + f * (ref.y(seg) - ref.y(seg - 1));
            z[k] = ref.z(seg - 1) + f * (ref.z(seg) - ref.z(seg - 1));
            ref.quaternion(seg - 1, q0);
            ref.quaternion(seg, q1);
            Rotations.slerp(q0, q1, f, q, 4 * k);
        }
    }

    /** @return number of poses */
    public int size() {
        return x.length;
    }

    @Override
    public double x(int k) {
        return x[k];
    }

    @Override
    public double y(int k) {
        return y[k];
    }

    @Override
    public double z(int k) {
        return z == null ? 0.0 : z[k];
    }

    /** @return the interpolated yaw of pose k (rad); planar references only */
    public double yaw(int k) {
        return yaw[k];
    }

    /** @return true when the reference is planar (rotations about +z by {@link #yaw}) */
    public boolean isPlanar() {
        return yaw != null;
    }

    /** Writes the rotation matrix of pose k (row-major) into {@code out[o..o+9)}. */
    public void rotation(int k, double[] out, int o) {
        if (yaw != null) {
            Rotations.aboutZ(yaw[k], out, o);
        } else {
            Rotations.fromQuaternion(q[4 * k], q[4 * k + 1], q[4 * k + 2], q[4 * k + 3], out, o);
        }
    }

    /** @return the poses as a materialised sequence (rotation matrices, z = 0 for planar data) */
    public PoseSequence toPoses() {
        int n = x.length;
        double[] r = new double[9 * n];
        for (int k = 0; k < n; k++) {
            rotation(k, r, 9 * k);
        }
        return PoseSequence.of(x.clone(), y.clone(), z == null ? new double[n] : z.clone(), r);
    }
}
