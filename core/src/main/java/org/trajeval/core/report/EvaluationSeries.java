package org.trajeval.core.report;

import java.util.Arrays;
import java.util.Objects;
import org.trajeval.core.eval.Evaluation;
import org.trajeval.core.metric.SubTrajectoryErrors;

/**
 * The per-pose and per-pair series behind one evaluation, for plots and for saving beside the
 * summary ({@code --save-series}): what evo keeps with {@code --save_results}, and more.
 *
 * <p>Time is relative to the first associated pose: {@code t_k = stamp_k - stamp_0} (s), or the
 * frame index when the files had no stamps ({@link #timeUnit} {@code frame}), so a TUM recording
 * starts at 0 s and not at 1.3e9 s.
 *
 * @param timeUnit "s" or "frame"
 * @param poses one row per associated pose
 * @param pairs one row per RPE pair
 * @param segments one row per sub-trajectory (relative error per length), possibly none
 */
public record EvaluationSeries(String timeUnit, Poses poses, Pairs pairs, Segments segments) {

    /** @throws IllegalArgumentException on an unknown time unit */
    public EvaluationSeries {
        Objects.requireNonNull(poses, "poses");
        Objects.requireNonNull(pairs, "pairs");
        Objects.requireNonNull(segments, "segments");
        if (!"s".equals(timeUnit) && !"frame".equals(timeUnit)) {
            throw new IllegalArgumentException("time unit must be s or frame, found \"" + timeUnit + "\"");
        }
    }

    /** The series without sub-trajectory errors (a folder saved before they were). */
    public EvaluationSeries(String timeUnit, Poses poses, Pairs pairs) {
        this(timeUnit, poses, pairs, Segments.NONE);
    }

    /**
     * Per associated pose k.
     *
     * @param t time from the first pose (s, or frames)
     * @param refX reference x (m), likewise refY, refZ
     * @param estX aligned estimate x (m), likewise estY, estZ
     * @param ateTransM |p_est,k - p_ref,k| (m)
     * @param ateRotRad rotation angle of T_est,k^-1 T_ref,k (rad)
     */
    public record Poses(double[] t, double[] refX, double[] refY, double[] refZ, double[] estX, double[] estY,
            double[] estZ, double[] ateTransM, double[] ateRotRad) {

        /** @throws IllegalArgumentException when the columns differ in length */
        public Poses {
            int n = t.length;
            for (double[] c : new double[][] {refX, refY, refZ, estX, estY, estZ, ateTransM, ateRotRad}) {
                if (c.length != n) {
                    throw new IllegalArgumentException("pose columns must have " + n + " rows, found " + c.length);
                }
            }
        }

        /** @return number of poses */
        public int size() {
            return t.length;
        }
    }

    /**
     * Per RPE pair (i, j), at the time of its first pose.
     *
     * @param t time of pose i from the first pose (s, or frames)
     * @param horizon t_j - t_i (s, or frames)
     * @param rpeTransM |trans(E_ij)| (m)
     * @param rpeRotRad rotation angle of E_ij (rad)
     */
    public record Pairs(double[] t, double[] horizon, double[] rpeTransM, double[] rpeRotRad) {

        /** @throws IllegalArgumentException when the columns differ in length */
        public Pairs {
            int n = t.length;
            if (horizon.length != n || rpeTransM.length != n || rpeRotRad.length != n) {
                throw new IllegalArgumentException("pair columns must have " + n + " rows");
            }
        }

        /** @return number of pairs */
        public int size() {
            return t.length;
        }
    }

    /**
     * Per sub-trajectory ({@link SubTrajectoryErrors}), length by length, in the order of the starts.
     *
     * @param lengthM sub-trajectory length L (m)
     * @param t time of the start pose from the first pose (s, or frames)
     * @param transPct |trans(E)| / L x 100 (%)
     * @param rotDegPerM angle(E) / L (deg/m)
     */
    public record Segments(double[] lengthM, double[] t, double[] transPct, double[] rotDegPerM) {
        /** No segments. */
        public static final Segments NONE = new Segments(new double[0], new double[0], new double[0], new double[0]);

        /** @throws IllegalArgumentException when the columns differ in length */
        public Segments {
            int n = lengthM.length;
            if (t.length != n || transPct.length != n || rotDegPerM.length != n) {
                throw new IllegalArgumentException("segment columns must have " + n + " rows");
            }
        }

        /** @return number of segments */
        public int size() {
            return t.length;
        }

        /** @return the distinct lengths (m), in order of appearance */
        public double[] lengths() {
            return Arrays.stream(lengthM).distinct().toArray();
        }

        /** @return the values of one column for one length, e.g. {@code at(transPct(), 100.0)} */
        public double[] at(double[] column, double length) {
            int k = 0;
            double[] out = new double[lengthM.length];
            for (int i = 0; i < lengthM.length; i++) {
                if (lengthM[i] == length) {
                    out[k++] = column[i];
                }
            }
            return Arrays.copyOf(out, k);
        }
    }

    /** The series of an evaluation, with sub-trajectory errors at 10 ... 50 % of the path. */
    public static EvaluationSeries of(Evaluation e, boolean frames) {
        return of(e, frames, null);
    }

    /**
     * The series of an evaluation.
     *
     * @param e the evaluation ({@code Evaluator.run})
     * @param frames true when the stamps are pose indices (KITTI without a times file)
     * @param subTrajectoryLengthsM lengths of the sub-trajectory errors (m), or null for 10 ... 50 %
     *     of the reference path
     */
    public static EvaluationSeries of(Evaluation e, boolean frames, double[] subTrajectoryLengthsM) {
        double[] stamps = e.associated().timestamps();
        int n = stamps.length;
        double t0 = n == 0 ? 0.0 : stamps[0];
        double[] t = new double[n];
        for (int k = 0; k < n; k++) {
            t[k] = stamps[k] - t0;
        }
        var ref = e.reference();
        var est = e.alignedEstimate();
        double[][] rp = ref.positions(); // {x, y, z} columns
        double[][] ep = est.positions();
        Poses poses = new Poses(t, rp[0], rp[1], rp[2], ep[0], ep[1], ep[2], e.ate().transErrorsM(),
                e.ate().rotErrorsRad());
        int m = e.rpe().pairs();
        double[] pt = new double[m];
        double[] ph = new double[m];
        for (int k = 0; k < m; k++) {
            pt[k] = t[e.rpe().first()[k]];
            ph[k] = t[e.rpe().second()[k]] - pt[k];
        }
        return new EvaluationSeries(frames ? "frame" : "s", poses,
                new Pairs(pt, ph, e.rpe().transErrorsM(), e.rpe().rotErrorsRad()),
                segments(SubTrajectoryErrors.compute(ref, est, subTrajectoryLengthsM), t));
    }

    private static Segments segments(SubTrajectoryErrors s, double[] t) {
        int n = s.perLength().stream().mapToInt(SubTrajectoryErrors.AtLength::size).sum();
        double[] len = new double[n];
        double[] st = new double[n];
        double[] tr = new double[n];
        double[] rot = new double[n];
        int k = 0;
        for (SubTrajectoryErrors.AtLength a : s.perLength()) {
            for (int i = 0; i < a.size(); i++, k++) {
                len[k] = a.lengthM();
                st[k] = t[a.first()[i]];
                tr[k] = a.transPct()[i];
                rot[k] = a.rotDegPerM()[i];
            }
        }
        return new Segments(len, st, tr, rot);
    }
}
