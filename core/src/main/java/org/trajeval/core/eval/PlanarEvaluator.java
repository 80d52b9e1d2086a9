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
import org.trajeval.core.stats.ValueChunks;
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
        return planar && model && !o.extraMetrics() && o.association() == AssociationMethod.INTERPOLATE
                && (o.rpeUnit() == RpeUnit.SECONDS || o.rpeUnit() == RpeUnit.FRAMES) && o.drift() == null
                && o.projection() != PlanarProjection.XZ_AFTER_ALIGNMENT;
    }

    /** @return the report, or {@code null} when the general path must decide (refusals, edge cases) */
    static ReportParts evaluate(PlanarTrajectory ref, PlanarTrajectory est, EvaluationOptions o, String estName,
            Parallelism par) {
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
        int spanLo = 0;
        while (spanLo + 1 < nr && ref.t(spanLo + 1) <= est.t(k0) + off) {
            spanLo++;
        }
        int spanHi = nr - 1;
        while (spanHi - 1 > spanLo && ref.t(spanHi - 1) >= est.t(k1 - 1) + off) {
            spanHi--;
        }
        double[] sampling = referenceSampling(ref, spanLo, spanHi, par);
        if (sampling[0] > o.maxGap().limitS(ref)) {
            return null; // a reference gap longer than the limit: the general path drops and counts
        }
        Pair pair = new Pair(ref, est, k0, m, off);
        // ---- association: the reference interpolated at the estimate stamps (lesson's rule)
        par.forEachChunk(m, (c, from, to) -> pair.interpolate(from, to));

        // ---- alignment (closed form, same sums as the general path)
        AlignmentTransform tf = fit(o, est, k0, m, pair.xr, pair.yr, pair.dyaw, estName);
        pair.setAlignment(tf);

        // ---- errors and statistics, in an order that lets each pass overwrite what no later pass
        // reads: RPE trans (recomputed at each reading of the statistics, so no array of its
        // own), ATE trans into xr, RPE rot into yr, ATE rot into dyaw. Memory: three arrays.
        PairRule rule = o.pairSelection() == PairSelection.ALL_PAIRS && o.rpeDelta() > 0
                ? pair.new EveryStart(o.rpeDelta(), o.rpeUnit(), par)
                : pair.new Walk(new PairWalk(est, k0, m, off, o.rpeDelta(), o.rpeUnit(), o.pairSelection()));
        ErrorStatistics rpeTrans = ErrorStatistics.of(rule.translationErrors());
        par.forEachChunk(m, (c, from, to) -> pair.ateTransInto(pair.xr, from, to));
        ErrorStatistics ateTrans = ErrorStatistics.ofInPlace(pair.xr, m);
        rule.rotationErrorsInto(pair.yr);
        ErrorStatistics rpeRot = ErrorStatistics.ofInPlace(pair.yr, rule.pairs());
        par.forEachChunk(m, (c, from, to) -> pair.ateRotInto(pair.dyaw, from, to));
        ErrorStatistics ateRot = ErrorStatistics.ofInPlace(pair.dyaw, m);
        int pairs = rule.pairs();
        return new ReportParts(m, ne - m, sampling[0], sampling[1], tf, ateTrans, ateRot, rpeTrans, rpeRot,
                pairs, pairs == 0 ? Double.NaN : rule.sumS() / pairs, pairs == 0 ? Double.NaN : rule.sumM() / pairs);
    }

    /** @return {max gap (s), max acceleration (m/s^2)} of the reference over poses [lo, hi], chunk by chunk */
    private static double[] referenceSampling(PlanarTrajectory ref, int lo, int hi, Parallelism par) {
        int n = hi - lo + 1;
        double[] gap = new double[Parallelism.chunks(n)];
        double[] acc = new double[gap.length];
        par.forEachChunk(n, (c, from, to) -> {
            gap[c] = ReferenceSampling.maxGap(ref, lo + from, Math.min(lo + to, hi));
            acc[c] = ReferenceSampling.maxAcceleration(ref, lo + from, lo + to - 1);
        });
        double h = 0.0;
        double a = 0.0;
        for (int c = 0; c < gap.length; c++) {
            h = Math.max(h, gap[c]);
            a = Math.max(a, acc[c]);
        }
        return new double[] {h, a};
    }

    /** The RPE pairs of one pair-selection rule, with the sums behind the mean horizon. */
    private abstract static class PairRule {
        /** Number of pairs. */
        int pairs;
        /** Sum over pairs of t_j - t_i (s). */
        double sumS;
        /** Sum over pairs of the reference path length from i to j (m). */
        double sumM;

        final int pairs() {
            return pairs;
        }

        final double sumS() {
            return sumS;
        }

        final double sumM() {
            return sumM;
        }

        /** @return the translation errors of the pairs in pair order, computed afresh at each reading (m) */
        abstract ValueChunks translationErrors();

        /** Writes the rotation error of pair p to out[p] (rad); out may be yr, which no pair reads. */
        abstract void rotationErrorsInto(double[] out);
    }

    /**
     * The associated pair: the estimate poses [k0, k0 + m) and the reference interpolated at their
     * stamps (xr, yr in m; dyaw = estimate yaw - interpolated reference yaw, rad), and once fitted
     * the alignment (rotation cos/sin, scale, translation in m).
     */
    private static final class Pair {
        final PlanarTrajectory ref;
        final PlanarTrajectory est;
        final int k0;
        final int m;
        final double off;
        final double[] xr;
        final double[] yr;
        final double[] dyaw;
        double ca;
        double sa;
        double theta;
        double sc;
        double tx;
        double ty;

        Pair(PlanarTrajectory ref, PlanarTrajectory est, int k0, int m, double off) {
            this.ref = ref;
            this.est = est;
            this.k0 = k0;
            this.m = m;
            this.off = off;
            this.xr = new double[m];
            this.yr = new double[m];
            this.dyaw = new double[m];
        }

        /** Interpolates the reference at estimate poses [from, to): x, y linearly, yaw on the unit circle. */
        void interpolate(int from, int to) {
            int last = ref.size() - 1;
            int seg = ref.firstAtOrAfter(est.t(k0 + from) + off, 1, last); // last when none: the last segment
            double c0 = Math.cos(ref.yaw(seg - 1));
            double s0 = Math.sin(ref.yaw(seg - 1));
            double c1 = Math.cos(ref.yaw(seg));
            double s1 = Math.sin(ref.yaw(seg));
            for (int k = from; k < to; k++) {
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
                dyaw[k] = est.yaw(k0 + k) - Math.atan2(s0 + f * (s1 - s0), c0 + f * (c1 - c0));
            }
        }

        void setAlignment(AlignmentTransform tf) {
            double[] rot = tf.rotation();
            ca = rot[0];
            sa = rot[3];
            theta = Math.atan2(sa, ca);
            sc = tf.scale();
            tx = tf.translation()[0];
            ty = tf.translation()[1];
        }

        /** out[k] = |s R(theta) p_est,k + t - p_ref,k| (m); out may be xr (each k reads only its own xr[k], yr[k]) */
        void ateTransInto(double[] out, int from, int to) {
            for (int k = from; k < to; k++) {
                double px = sc * est.x(k0 + k);
                double py = sc * est.y(k0 + k);
                double dx = ca * px - sa * py + tx - xr[k];
                double dy = sa * px + ca * py + ty - yr[k];
                out[k] = Math.sqrt(dx * dx + dy * dy);
            }
        }

        /** out[k] = |wrap(yaw_est,k + theta - yaw_ref,k)| (rad); out may be dyaw */
        void ateRotInto(double[] out, int from, int to) {
            for (int k = from; k < to; k++) {
                out[k] = Math.abs(Angles.wrap(dyaw[k] + theta));
            }
        }

        /** @return |R(-delta_i)(p'_j - p'_i) - (p_ref,j - p_ref,i)| (m), delta_i the aligned yaw error at i */
        double rpeTrans(int i, int j) {
            // p'_j - p'_i = s R(theta) (p_j - p_i): the translation cancels
            double ex = sc * est.x(k0 + j) - sc * est.x(k0 + i);
            double ey = sc * est.y(k0 + j) - sc * est.y(k0 + i);
            double ax = ca * ex - sa * ey;
            double ay = sa * ex + ca * ey;
            double delta = dyaw[i] + theta;
            double cd = Math.cos(delta);
            double sd = Math.sin(delta);
            double dx = cd * ax + sd * ay - (xr[j] - xr[i]);
            double dy = -sd * ax + cd * ay - (yr[j] - yr[i]);
            return Math.sqrt(dx * dx + dy * dy);
        }

        /** @return |wrap(delta_j - delta_i)| (rad) */
        double rpeRot(int i, int j) {
            return Math.abs(Angles.wrap(dyaw[j] - dyaw[i]));
        }

        /** @return the length of the interpolated reference path from pose k to k + 1 (m) */
        double hop(int k) {
            double hx = xr[k] - xr[k + 1];
            double hy = yr[k] - yr[k + 1];
            return Math.sqrt(hx * hx + hy * hy);
        }

        /**
         * Reference path lengths between the poses of pairs met in order (i and j never decrease):
         * two running sums of {@link #hop}s from a start pose, to i and to j.
         */
        final class PathSpan {
            private int pathI;
            private int pathJ;
            private double toI; // path length from the start pose to i (m)
            private double toJ; // ... to j

            PathSpan(int start) {
                pathI = start;
                pathJ = start;
            }

            /** @return the reference path length from pose i to pose j (m) */
            double between(int i, int j) {
                while (pathI < i) {
                    toI += hop(pathI++);
                }
                if (pathJ < pathI) {
                    pathJ = pathI;
                    toJ = toI;
                }
                while (pathJ < j) {
                    toJ += hop(pathJ++);
                }
                return toJ - toI;
            }
        }

        /** The RPE pairs of the walk's rules, walked again at each reading (pairs that chain, e.g. consecutive). */
        final class Walk extends PairRule {
            private final PairWalk walk;

            Walk(PairWalk walk) {
                this.walk = walk;
                PathSpan path = new PathSpan(0);
                for (walk.start(); walk.next();) {
                    int i = walk.i();
                    int j = walk.j();
                    pairs++;
                    sumS += est.t(k0 + j) - est.t(k0 + i);
                    sumM += path.between(i, j);
                }
            }

            @Override
            ValueChunks translationErrors() {
                return ValueChunks.of(pairs, sink -> {
                    double[] chunk = new double[Math.min(Parallelism.CHUNK, Math.max(pairs, 1))];
                    int len = 0;
                    for (walk.start(); walk.next();) {
                        chunk[len++] = rpeTrans(walk.i(), walk.j());
                        if (len == chunk.length) {
                            sink.accept(chunk, len);
                            len = 0;
                        }
                    }
                    if (len > 0) {
                        sink.accept(chunk, len);
                    }
                });
            }

            @Override
            void rotationErrorsInto(double[] out) {
                int p = 0;
                for (walk.start(); walk.next();) {
                    out[p++] = rpeRot(walk.i(), walk.j()); // p <= i: nothing read later is overwritten
                }
            }
        }

        /**
         * RPE from every start pose i = 0, 1, ...: pair p starts at pose p, so chunks of start
         * poses are independent. The pairs end at the first start pose without a partner.
         */
        final class EveryStart extends PairRule {
            private final double delta;
            private final boolean frames;
            private final Parallelism par;

            EveryStart(double delta, RpeUnit unit, Parallelism par) {
                this.delta = delta;
                this.frames = unit == RpeUnit.FRAMES;
                this.par = par;
                int chunks = Parallelism.chunks(m);
                int[] firstWithout = new int[chunks];
                double[] chunkS = new double[chunks];
                double[] chunkM = new double[chunks];
                par.forEachChunk(m, (c, from, to) -> {
                    double s = 0;
                    double len = 0;
                    PathSpan path = new PathSpan(from);
                    int j = frames ? from : firstPartner(from, delta);
                    int i = from;
                    for (; i < to; i++) {
                        j = partner(i, j);
                        if (j >= m || j == i && !frames) {
                            break;
                        }
                        s += est.t(k0 + j) - est.t(k0 + i);
                        len += path.between(i, j);
                    }
                    firstWithout[c] = i;
                    chunkS[c] = s;
                    chunkM[c] = len;
                });
                pairs = m;
                for (int c = 0; c < chunks; c++) {
                    sumS += chunkS[c];
                    sumM += chunkM[c];
                    if (firstWithout[c] < Math.min((long) (c + 1) * Parallelism.CHUNK, m)) {
                        pairs = firstWithout[c];
                        break;
                    }
                }
            }

            /** @return the partner of start pose i, given the partner j of an earlier start in the same chunk */
            private int partner(int i, int j) {
                return frames ? partnerInFrames(i, delta) : nextPartner(i, j, delta);
            }

            @Override
            ValueChunks translationErrors() {
                return ValueChunks.of(pairs, sink -> {
                    // a window of one chunk per thread is computed at once, then handed over in order
                    int chunks = Parallelism.chunks(pairs);
                    int window = par.threads();
                    double[][] scratch = new double[Math.min(window, Math.max(chunks, 1))][];
                    for (int first = 0; first < chunks; first += window) {
                        int start = first;
                        int count = Math.min(window, chunks - first);
                        par.forEach(count, q -> {
                            int from = (start + q) * Parallelism.CHUNK;
                            int to = (int) Math.min((long) from + Parallelism.CHUNK, pairs);
                            if (scratch[q] == null) {
                                scratch[q] = new double[Math.min(Parallelism.CHUNK, pairs)];
                            }
                            double[] out = scratch[q];
                            int j = frames ? from : firstPartner(from, delta);
                            for (int i = from; i < to; i++) {
                                j = partner(i, j);
                                out[i - from] = rpeTrans(i, j);
                            }
                        });
                        for (int q = 0; q < count; q++) {
                            int from = (start + q) * Parallelism.CHUNK;
                            sink.accept(scratch[q], (int) Math.min((long) Parallelism.CHUNK, pairs - from));
                        }
                    }
                });
            }

            @Override
            void rotationErrorsInto(double[] out) {
                par.forEachChunk(pairs, (c, from, to) -> {
                    int j = frames ? from : firstPartner(from, delta);
                    for (int i = from; i < to; i++) {
                        j = partner(i, j);
                        out[i] = rpeRot(i, j);
                    }
                });
            }
        }

        /** @return i + delta (frames), or m when that is past the last pose */
        private int partnerInFrames(int i, double delta) {
            long j = (long) i + (int) delta;
            return j >= m ? m : (int) j;
        }

        /** @return the first pose j &gt;= i with t_j + off &gt;= (t_i + off) + delta (s), or m (binary search) */
        private int firstPartner(int i, double delta) {
            double target = (est.t(k0 + i) + off) + delta;
            int lo = i;
            int hi = m;
            while (lo < hi) {
                int mid = (lo + hi) >>> 1;
                if (est.t(k0 + mid) + off < target) {
                    lo = mid + 1;
                } else {
                    hi = mid;
                }
            }
            return lo;
        }

        /** As {@link #firstPartner}, walking on from {@code j}, the partner of an earlier start pose. */
        private int nextPartner(int i, int j, double delta) {
            double target = (est.t(k0 + i) + off) + delta;
            j = Math.max(i, j);
            while (j < m && est.t(k0 + j) + off < target) {
                j++;
            }
            return j;
        }
    }

    private static AlignmentTransform fit(EvaluationOptions o, PlanarTrajectory est, int k0, int m, double[] xr,
            double[] yr, double[] dyaw, String estName) {
        AlignmentModel model = o.alignment();
        if (model == AlignmentModel.NONE) {
            return AlignmentTransform.identity(0);
        }
        if (model == AlignmentModel.ORIGIN) {
            double theta = -dyaw[0]; // reference yaw - estimate yaw at the first pose
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
