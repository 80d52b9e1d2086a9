package org.trajeval.core.eval;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.report.EvaluationReport.Warning;
import org.trajeval.core.traj.PositionColumns;

/**
 * Names a fitted alignment that cannot be trusted, each with the option that avoids it:
 * <ul>
 * <li>{@value #FLIPS_PLANE}: a 3D fit (se3, sim3) of planar data whose rotation turns the plane
 *     upside down (R_zz < 0: a rotation of 180 deg about an in-plane axis), so the estimate is
 *     scored as its mirror image in the plane (evo does this silently with -a on planar data);</li>
 * <li>{@value #UNOBSERVABLE}: positions so close to a line (the second principal spread below
 *     {@value #COLLINEAR_RATIO} of the first) that a 3D rotation about the line is not determined;</li>
 * <li>{@value #SCALE}: a sim2/sim3 scale outside [1/{@value #SCALE_LIMIT}, {@value #SCALE_LIMIT}],
 *     which hides a scale error when the estimate is metric (stereo, RGB-D, VIO, wheel odometry).</li>
 * </ul>
 */
final class AlignmentCheck {
    /** Code of a fit that mirrors planar data. */
    static final String FLIPS_PLANE = "alignment_flips_plane";
    /** Code of a fit whose rotation is not observable. */
    static final String UNOBSERVABLE = "alignment_rotation_unobservable";
    /** Code of a similarity scale far from 1. */
    static final String SCALE = "alignment_scale_far_from_one";
    /** Second over first principal spread (standard deviations) below which positions count as a line. */
    static final double COLLINEAR_RATIO = 1e-3;
    /** Scale factor beyond which (or below whose inverse) a sim fit is named. */
    static final double SCALE_LIMIT = 2.0;
    /** z spread over xy extent below which a trajectory counts as planar. */
    static final double PLANAR_RATIO = 1e-6;

    private AlignmentCheck() {
    }

    /**
     * @param tf the fitted transform
     * @param ref associated reference poses (the first {@code tf.posesUsed()} were fitted on)
     * @param est associated estimate poses, before alignment
     * @param size number of associated poses
     * @param planarData whether both trajectories are planar SE(2) data (or projected to it)
     * @return the warnings, possibly none
     */
    static List<Warning> check(AlignmentTransform tf, PositionColumns ref, PositionColumns est, int size,
            boolean planarData) {
        return check(tf, ref, est, size, planarData, null);
    }

    /**
     * As {@link #check(AlignmentTransform, PositionColumns, PositionColumns, int, boolean)}, with
     * the reference's principal spreads computed beforehand (e.g. beside the fit, on another thread).
     *
     * @param refSpreads {@link #principalSpreads} of the first min(tf.posesUsed(), size) reference
     *     positions, or null to compute them here when {@link #needsSpreads} says so
     */
    static List<Warning> check(AlignmentTransform tf, PositionColumns ref, PositionColumns est, int size,
            boolean planarData, double[] refSpreads) {
        List<Warning> out = new ArrayList<>();
        AlignmentModel m = tf.model();
        boolean spatialModel = m == AlignmentModel.SE3 || m == AlignmentModel.SIM3;
        int n = Math.min(tf.posesUsed(), size);
        if (spatialModel && tf.rotation()[8] < 0.0 && (planarData || (flat(ref, n) && flat(est, n)))) {
            out.add(new Warning(FLIPS_PLANE, String.format(Locale.ROOT, "the %s alignment turns the plane of this "
                    + "planar data upside down (R_zz = %.3f: a 180 deg rotation about an in-plane axis), so the "
                    + "estimate is scored as its mirror image; use --align se2 (or posyaw) for planar data", name(m),
                    tf.rotation()[8])));
        }
        if (needsSpreads(m, n)) {
            double[] sd = refSpreads != null ? refSpreads : principalSpreads(ref, n);
            if (sd[1] <= COLLINEAR_RATIO * sd[0]) {
                out.add(new Warning(UNOBSERVABLE, String.format(Locale.ROOT, "the %d positions the %s alignment is "
                        + "fitted on lie on a line (spread %.3g m across it, %.3g m along it): the rotation about "
                        + "that line is not determined; use --align posyaw or se2 for planar motion, or fit on more "
                        + "of the run (--n-to-align)", n, name(m), sd[1], sd[0])));
            }
        }
        Warning s = scale(tf);
        if (s != null) {
            out.add(s);
        }
        return out;
    }

    /** @return whether the check of a fit of this model on n poses needs the reference's principal spreads */
    static boolean needsSpreads(AlignmentModel model, int n) {
        return (model == AlignmentModel.SE3 || model == AlignmentModel.SIM3) && n >= 2;
    }

    /** @return the scale warning of a sim fit, or {@code null} */
    static Warning scale(AlignmentTransform tf) {
        boolean sim = tf.model() == AlignmentModel.SIM2 || tf.model() == AlignmentModel.SIM3;
        if (!sim || (tf.scale() <= SCALE_LIMIT && tf.scale() >= 1.0 / SCALE_LIMIT)) {
            return null;
        }
        return new Warning(SCALE, String.format(Locale.ROOT, "the %s alignment scales the estimate by %.4g; "
                + "expected for monocular estimates (no metric scale), but for a metric estimate (stereo, RGB-D, "
                + "VIO, wheel odometry) it hides a scale error: use --align %s to see it", name(tf.model()),
                tf.scale(), tf.model() == AlignmentModel.SIM2 ? "se2" : "se3"));
    }

    private static String name(AlignmentModel m) {
        return m.name().toLowerCase(Locale.ROOT);
    }

    /** @return whether z varies by at most PLANAR_RATIO of the xy extent over the first n poses */
    private static boolean flat(PositionColumns p, int n) {
        double zMin = Double.POSITIVE_INFINITY;
        double zMax = Double.NEGATIVE_INFINITY;
        double xMin = Double.POSITIVE_INFINITY;
        double xMax = Double.NEGATIVE_INFINITY;
        double yMin = Double.POSITIVE_INFINITY;
        double yMax = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            zMin = Math.min(zMin, p.z(i));
            zMax = Math.max(zMax, p.z(i));
            xMin = Math.min(xMin, p.x(i));
            xMax = Math.max(xMax, p.x(i));
            yMin = Math.min(yMin, p.y(i));
            yMax = Math.max(yMax, p.y(i));
        }
        double extent = Math.max(xMax - xMin, yMax - yMin);
        return zMax - zMin <= PLANAR_RATIO * extent;
    }

    /**
     * @return the principal standard deviations {sd1 >= sd2 >= sd3} (m) of the first n positions:
     *     square roots of the eigenvalues of their covariance (closed form for a symmetric 3x3 matrix,
     *     O. K. Smith, Comm. ACM 4(4), 1961)
     */
    static double[] principalSpreads(PositionColumns p, int n) {
        return principalSpreads(p, n, p.centroid(n));
    }

    /** As {@link #principalSpreads(PositionColumns, int)}, given {@code p.centroid(n)} (m). */
    static double[] principalSpreads(PositionColumns p, int n, double[] m) {
        double mx = m[0];
        double my = m[1];
        double mz = m[2];
        double a00 = 0;
        double a01 = 0;
        double a02 = 0;
        double a11 = 0;
        double a12 = 0;
        double a22 = 0;
        for (int i = 0; i < n; i++) {
            double dx = p.x(i) - mx;
            double dy = p.y(i) - my;
            double dz = p.z(i) - mz;
            a00 += dx * dx;
            a01 += dx * dy;
            a02 += dx * dz;
            a11 += dy * dy;
            a12 += dy * dz;
            a22 += dz * dz;
        }
        a00 /= n;
        a01 /= n;
        a02 /= n;
        a11 /= n;
        a12 /= n;
        a22 /= n;
        double p1 = a01 * a01 + a02 * a02 + a12 * a12;
        double q = (a00 + a11 + a22) / 3.0;
        double p2 = (a00 - q) * (a00 - q) + (a11 - q) * (a11 - q) + (a22 - q) * (a22 - q) + 2.0 * p1;
        double e1;
        double e2;
        double e3;
        if (p2 <= 0.0) {
            e1 = e2 = e3 = q;
        } else {
            double pp = Math.sqrt(p2 / 6.0);
            double b00 = (a00 - q) / pp;
            double b11 = (a11 - q) / pp;
            double b22 = (a22 - q) / pp;
            double b01 = a01 / pp;
            double b02 = a02 / pp;
            double b12 = a12 / pp;
            double det = b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) + b02 * (b01 * b12 - b11 * b02);
            double r = Math.max(-1.0, Math.min(1.0, det / 2.0));
            double phi = Math.acos(r) / 3.0;
            e1 = q + 2.0 * pp * Math.cos(phi);
            e3 = q + 2.0 * pp * Math.cos(phi + 2.0 * Math.PI / 3.0);
            e2 = 3.0 * q - e1 - e3;
        }
        return new double[] {Math.sqrt(Math.max(0.0, e1)), Math.sqrt(Math.max(0.0, e2)),
            Math.sqrt(Math.max(0.0, e3))};
    }
}
