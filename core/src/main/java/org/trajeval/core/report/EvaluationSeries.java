package org.trajeval.core.report;

import java.util.Objects;
import org.trajeval.core.eval.Evaluation;

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
 */
public record EvaluationSeries(String timeUnit, Poses poses, Pairs pairs) {

    /** @throws IllegalArgumentException on an unknown time unit */
    public EvaluationSeries {
        Objects.requireNonNull(poses, "poses");
        Objects.requireNonNull(pairs, "pairs");
        if (!"s".equals(timeUnit) && !"frame".equals(timeUnit)) {
            throw new IllegalArgumentException("time unit must be s or frame, found \"" + timeUnit + "\"");
        }
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
     * The series of an evaluation.
     *
     * @param e the evaluation ({@code Evaluator.run})
     * @param frames true when the stamps are pose indices (KITTI without a times file)
     */
    public static EvaluationSeries of(Evaluation e, boolean frames) {
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
                new Pairs(pt, ph, e.rpe().transErrorsM(), e.rpe().rotErrorsRad()));
    }
}
