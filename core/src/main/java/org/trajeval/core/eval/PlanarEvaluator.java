package org.trajeval.core.eval;

import org.trajeval.core.align.Alignment;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.assoc.ReferenceSampling;
import org.trajeval.core.geom.Angles;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.metric.PairSelection;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.stats.ErrorStatistics;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * The planar fast path: the same numbers as the general SE(3) path for planar pairs with the
 * lesson's interpolated association, computed on primitive columns without per-pose matrices.
 * Memory: the interpolated reference (x, y, yaw: 24 B per pose) and one error buffer (8 B per
 * pose) on top of the inputs. Per pose k, with the fitted planar transform (theta, s, t):
 * p'_k = s R(theta) p_est,k + t, yaw'_k = yaw_est,k + theta, delta_k = yaw'_k - yaw_ref,k;
 * ATE: |p'_k - p_ref,k| and |wrap(delta_k)|; RPE for a pair (i, j):
 * |R(-delta_i)(p'_j - p'_i) - (p_ref,j - p_ref,i)| and |wrap(delta_j - delta_i)|.
 */
final class PlanarEvaluator {
    private PlanarEvaluator() {
    }

    /** @return true when the fast path computes these options for this pair exactly as the general path */
    static boolean applies(LoadedTrajectory ref, LoadedTrajectory est, EvaluationOptions o) {
        boolean planar = ref.trajectory() instanceof PlanarTrajectory && est.trajectory() instanceof PlanarTrajectory;
        boolean model = switch (o.alignment()) {
            case NONE, SE2, SIM2, ORIGIN -> true;
            default -> false;
        };
        return planar && model && o.association() == AssociationMethod.INTERPOLATE
                && (o.rpeUnit() == RpeUnit.SECONDS || o.rpeUnit() == RpeUnit.FRAMES) && o.drift() == null
                && o.projection() != PlanarProjection.XZ_AFTER_ALIGNMENT;
    }

    /** @return the report, or {@code null} when the general path must decide (refusals, edge cases) */
    static ReportParts evaluate(PlanarTrajectory ref, PlanarTrajectory est, EvaluationOptions o, String estName) {
        int nr = ref.size();
        int ne = est.size();
        if (nr < 2) {
            return null;
        }
        double off = o.tOffsetS();
        double t0 = ref.t(0);
        double tn = ref.t(nr - 1);
        int k0 = 0;
        while (k0 < ne && est.t(k0) + off < t0) {
            k0++;
        }
        int k1 = ne;
        while (k1 > k0 && est.t(k1 - 1) + off > tn) {
            k1--;
        }
        int m = k1 - k0;
        if (m < 2 || (o.overlap() == OverlapPolicy.STRICT && m != ne)) {
            return null;
        }
        // ---- association: the reference interpolated at the estimate stamps (lesson's rule)
        double[] xr = new double[m];
        double[] yr = new double[m];
        double[] yawr = new double[m];
        int seg = 1;
        int last = nr - 1;
        double c0 = Math.cos(ref.yaw(0));
        double s0 = Math.sin(ref.yaw(0));
        double c1 = Math.cos(ref.yaw(1));
        double s1 = Math.sin(ref.yaw(1));
        for (int k = 0; k < m; k++) {
            double t = est.t(k0 + k) + off;
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
            xr[k] = ref.x(seg - 1) + f * (ref.x(seg) - ref.x(seg - 1));
            yr[k] = ref.y(seg - 1) + f * (ref.y(seg) - ref.y(seg - 1));
            yawr[k] = Math.atan2(s0 + f * (s1 - s0), c0 + f * (c1 - c0));
        }
        int spanLo = 0;
        while (spanLo + 1 < nr && ref.t(spanLo + 1) <= est.t(k0) + off) {
            spanLo++;
        }
        int spanHi = nr - 1;
        while (spanHi - 1 > spanLo && ref.t(spanHi - 1) >= est.t(k1 - 1) + off) {
            spanHi--;
        }
        double maxGap = ReferenceSampling.maxGap(ref, spanLo, spanHi);
        double aMax = ReferenceSampling.maxAcceleration(ref, spanLo, spanHi);

        // ---- alignment (closed form, same sums as the general path)
        AlignmentTransform tf = fit(o, est, k0, m, xr, yr, yawr, estName);
        double[] rot = tf.rotation();
        double ca = rot[0];
        double sa = rot[3];
        double theta = Math.atan2(sa, ca);
        double sc = tf.scale();
        double[] tt = tf.translation();
        double tx = tt[0];
        double ty = tt[1];

        // ---- ATE
        double[] buf = new double[m];
        for (int k = 0; k < m; k++) {
            double px = sc * est.x(k0 + k);
            double py = sc * est.y(k0 + k);
            double ax = ca * px - sa * py + tx;
            double ay = sa * px + ca * py + ty;
            double dx = ax - xr[k];
            double dy = ay - yr[k];
            buf[k] = Math.sqrt(dx * dx + dy * dy);
        }
        ErrorStatistics ateTrans = ErrorStatistics.ofInPlace(buf, m);
        for (int k = 0; k < m; k++) {
            buf[k] = Math.abs(Angles.wrap(est.yaw(k0 + k) + theta - yawr[k]));
        }
        ErrorStatistics ateRot = ErrorStatistics.ofInPlace(buf, m);

        // ---- RPE pairs on the estimate stamps (the pair rules of PairIndices, inlined)
        PairWalk walk = new PairWalk(est, k0, m, off, o.rpeDelta(), o.rpeUnit(), o.pairSelection());
        int pairs = 0;
        double sumS = 0;
        double sumM = 0;
        double dI = 0; // reference path length from pose 0 to i (m)
        double dJ = 0; // ... to j
        int pathI = 0;
        int pathJ = 0;
        for (walk.start(); walk.next();) {
            int i = walk.i();
            int j = walk.j();
            double ix = sc * est.x(k0 + i);
            double iy = sc * est.y(k0 + i);
            double jx = sc * est.x(k0 + j);
            double jy = sc * est.y(k0 + j);
            // p'_j - p'_i = s R(theta) (p_j - p_i): the translation cancels
            double ex = jx - ix;
            double ey = jy - iy;
            double ax = ca * ex - sa * ey;
            double ay = sa * ex + ca * ey;
            double delta = est.yaw(k0 + i) + theta - yawr[i];
            double cd = Math.cos(delta);
            double sd = Math.sin(delta);
            double vx = cd * ax + sd * ay;
            double vy = -sd * ax + cd * ay;
            double bx = xr[j] - xr[i];
            double by = yr[j] - yr[i];
            double dx = vx - bx;
            double dy = vy - by;
            buf[pairs++] = Math.sqrt(dx * dx + dy * dy);
            sumS += est.t(k0 + j) - est.t(k0 + i);
            while (pathI < i) {
                double hx = xr[pathI] - xr[pathI + 1];
                double hy = yr[pathI] - yr[pathI + 1];
                dI += Math.sqrt(hx * hx + hy * hy);
                pathI++;
            }
            if (pathJ < pathI) {
                pathJ = pathI;
                dJ = dI;
            }
            while (pathJ < j) {
                double hx = xr[pathJ] - xr[pathJ + 1];
                double hy = yr[pathJ] - yr[pathJ + 1];
                dJ += Math.sqrt(hx * hx + hy * hy);
                pathJ++;
            }
            sumM += dJ - dI;
        }
        ErrorStatistics rpeTrans = ErrorStatistics.ofInPlace(buf, pairs);
        int p = 0;
        for (walk.start(); walk.next();) {
            int i = walk.i();
            int j = walk.j();
            double di = est.yaw(k0 + i) - yawr[i];
            double dj = est.yaw(k0 + j) - yawr[j];
            buf[p++] = Math.abs(Angles.wrap(dj - di));
        }
        ErrorStatistics rpeRot = ErrorStatistics.ofInPlace(buf, pairs);
        return new ReportParts(m, ne - m, maxGap, aMax, tf, ateTrans, ateRot, rpeTrans, rpeRot, pairs,
                pairs == 0 ? Double.NaN : sumS / pairs, pairs == 0 ? Double.NaN : sumM / pairs);
    }

    private static AlignmentTransform fit(EvaluationOptions o, PlanarTrajectory est, int k0, int m, double[] xr,
            double[] yr, double[] yawr, String estName) {
        AlignmentModel model = o.alignment();
        if (model == AlignmentModel.NONE) {
            return AlignmentTransform.identity(0);
        }
        if (model == AlignmentModel.ORIGIN) {
            double theta = yawr[0] - est.yaw(k0);
            double c = Math.cos(theta);
            double s = Math.sin(theta);
            double tx = xr[0] - (c * est.x(k0) - s * est.y(k0));
            double ty = yr[0] - (s * est.x(k0) + c * est.y(k0));
            return new AlignmentTransform(AlignmentModel.ORIGIN, new double[] {c, -s, 0, s, c, 0, 0, 0, 1},
                    new double[] {tx, ty, 0}, 1.0, 1);
        }
        int n = o.nToAlign() < 0 ? m : Math.min(o.nToAlign(), m);
        double mex = 0;
        double mey = 0;
        double mgx = 0;
        double mgy = 0;
        for (int i = 0; i < n; i++) {
            mex += est.x(k0 + i);
            mey += est.y(k0 + i);
            mgx += xr[i];
            mgy += yr[i];
        }
        mex /= n;
        mey /= n;
        mgx /= n;
        mgy /= n;
        double a = 0;
        double b = 0;
        double ee = 0;
        for (int i = 0; i < n; i++) {
            double ex = est.x(k0 + i) - mex;
            double ey = est.y(k0 + i) - mey;
            double gx = xr[i] - mgx;
            double gy = yr[i] - mgy;
            a += ex * gx + ey * gy;
            b += ex * gy - ey * gx;
            ee += ex * ex + ey * ey;
        }
        return Alignment.planarFromSums(model, n, new double[] {mex, mey, 0}, new double[] {mgx, mgy, 0}, a, b, ee,
                estName);
    }

    /** Index pairs on the associated estimate poses, by the rules of the general path. */
    private static final class PairWalk {
        private final PlanarTrajectory est;
        private final int k0;
        private final int m;
        private final double off;
        private final double delta;
        private final RpeUnit unit;
        private final boolean all;
        private int i;
        private int j;
        private boolean first;

        PairWalk(PlanarTrajectory est, int k0, int m, double off, double delta, RpeUnit unit, PairSelection sel) {
            this.est = est;
            this.k0 = k0;
            this.m = m;
            this.off = off;
            this.delta = delta;
            this.unit = unit;
            this.all = sel == PairSelection.ALL_PAIRS;
        }

        void start() {
            i = 0;
            j = 0;
            first = true;
        }

        int i() {
            return i;
        }

        int j() {
            return j;
        }

        /** Advances to the next pair; false when there is none. */
        boolean next() {
            if (unit == RpeUnit.FRAMES) {
                int d = (int) delta;
                if (first) {
                    first = false;
                    i = 0;
                } else {
                    i += all ? 1 : d;
                }
                j = i + d;
                return j < m;
            }
            if (first) {
                first = false;
                i = 0;
            } else if (all) {
                i++;
            } else {
                if (j == i) {
                    return false;
                }
                i = j;
            }
            if (i >= m) {
                return false;
            }
            double target = (est.t(k0 + i) + off) + delta;
            if (j < i) {
                j = i;
            }
            while (j < m && est.t(k0 + j) + off < target) {
                j++;
            }
            return j < m && j != i;
        }
    }

    /** What the fast path computed; the evaluator turns it into the report. */
    record ReportParts(int matched, int dropped, double maxGapS, double aMaxMps2, AlignmentTransform alignment,
            ErrorStatistics ateTrans, ErrorStatistics ateRot, ErrorStatistics rpeTrans, ErrorStatistics rpeRot,
            int pairs, double meanHorizonS, double meanHorizonM) {
    }
}
