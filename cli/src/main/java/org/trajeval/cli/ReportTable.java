package org.trajeval.cli;

import java.util.Locale;
import org.trajeval.core.report.EvaluationReport;

/** Renders an evaluation report as a readable table (units in every row). */
final class ReportTable {
    private ReportTable() {
    }

    static String render(EvaluationReport r) {
        StringBuilder sb = new StringBuilder();
        EvaluationReport.InputInfo ref = r.inputs().reference();
        EvaluationReport.InputInfo est = r.inputs().estimate();
        sb.append(String.format(Locale.ROOT, "reference  %s (%s, %d poses; %s)%n", ref.path(), ref.format(),
                ref.poses(), ref.formatReason()));
        sb.append(String.format(Locale.ROOT, "estimate   %s (%s, %d poses; %s)%n", est.path(), est.format(),
                est.poses(), est.formatReason()));
        EvaluationReport.AssociationInfo a = r.association();
        sb.append(String.format(Locale.ROOT, "convention %s; association %s: %d matched, %d estimate poses dropped",
                r.convention(), a.method(), a.matched(), a.dropped()));
        if (!"interpolate".equals(a.method())) {
            sb.append(String.format(Locale.ROOT, ", max diff %.4g s", a.maxDiffS()));
        }
        if (a.tOffsetS() != 0.0) {
            sb.append(String.format(Locale.ROOT, ", offset %.4g s", a.tOffsetS()));
        }
        sb.append(String.format(Locale.ROOT, "%n           reference max gap h = %.4g s", a.maxGapS()));
        if (a.gapLimitS() != null) {
            sb.append(String.format(Locale.ROOT, " (interpolation bridges gaps up to %.4g s)", a.gapLimitS()));
        }
        if (a.interpErrorBoundM() != null) {
            sb.append(String.format(Locale.ROOT, ", interpolation error bound A_max h^2/8 = %.3g m (A_max %.3g m/s^2)",
                    a.interpErrorBoundM(), a.aMaxMps2()));
        }
        sb.append(System.lineSeparator());
        if (a.droppedInGaps() > 0) {
            sb.append(String.format(Locale.ROOT, "           %d estimate poses dropped inside %d reference gaps longer "
                    + "than %.4g s:", a.droppedInGaps(), a.gaps().size(), a.gapLimitS()));
            int shown = 0;
            for (EvaluationReport.Gap g : a.gaps()) {
                if (shown++ == 3) {
                    sb.append(" ...");
                    break;
                }
                sb.append(String.format(Locale.ROOT, " %d in [%.3f, %.3f] s (%.3f s)%s", g.dropped(), g.startS(),
                        g.endS(), g.lengthS(), shown < Math.min(3, a.gaps().size()) ? ";" : ""));
            }
            sb.append(System.lineSeparator());
        }
        EvaluationReport.CoverageInfo c = r.coverage();
        if (c != null) {
            sb.append(String.format(Locale.ROOT, "coverage   %.1f %% of the reference's %.3f s; longest stretch without "
                    + "an estimate %.3f s (from %.3f s)%n", 100.0 * c.fraction(), c.referenceSpanS(), c.longestGapS(),
                    c.longestGapStartS()));
        }
        EvaluationReport.AlignmentInfo al = r.alignment();
        double[][] rot = al.rotation();
        double yaw = Math.toDegrees(Math.atan2(rot[1][0], rot[0][0]));
        sb.append(String.format(Locale.ROOT, "alignment  %s on %d poses: translation (%.4f, %.4f, %.4f) m, yaw %.4f deg,"
                + " scale %.6f%n", al.model(), al.posesUsed(), al.translationM()[0], al.translationM()[1],
                al.translationM()[2], yaw, al.scale()));
        if (r.drift() != null && "kitti".equals(r.convention())) {
            sb.append(drift(r.drift())); // the KITTI convention's headline
        }
        sb.append(System.lineSeparator());
        sb.append(String.format(Locale.ROOT, "%-16s %12s %12s %12s %12s %12s %12s %8s%n", "metric", "rmse", "mean",
                "median", "std", "min", "max", "n"));
        row(sb, "ATE trans (m)", r.ate().transM(), 1.0);
        row(sb, "ATE rot (deg)", r.ate().rotRad(), 180.0 / Math.PI);
        row(sb, "RPE trans (m)", r.rpe().transM(), 1.0);
        row(sb, "RPE rot (deg)", r.rpe().rotRad(), 180.0 / Math.PI);
        EvaluationReport.Rpe rpe = r.rpe();
        sb.append(String.format(Locale.ROOT, "RPE: delta %s %s, %s, chosen on the %s: %d pairs", fmt(rpe.delta()),
                rpe.unit(), "all_pairs".equals(rpe.pairSelection()) ? "every start pose" : "consecutive pairs",
                rpe.pairsFrom(), rpe.pairs()));
        if (rpe.meanHorizonS() != null) {
            sb.append(String.format(Locale.ROOT, ", mean horizon %.4g s / %.4g m", rpe.meanHorizonS(),
                    rpe.meanHorizonM()));
        }
        sb.append(System.lineSeparator());
        if (r.drift() != null && !"kitti".equals(r.convention())) {
            sb.append(drift(r.drift()));
        }
        for (EvaluationReport.Warning w : r.warnings()) {
            sb.append("WARNING ").append(w.code()).append(": ").append(w.message()).append(System.lineSeparator());
        }
        return sb.toString();
    }

    private static String drift(EvaluationReport.Drift d) {
        return String.format(Locale.ROOT, "drift: %s %% translation, %s deg/m rotation over %d segments%n",
                d.transPct() == null ? "n/a" : String.format(Locale.ROOT, "%.4f", d.transPct()),
                d.rotDegPerM() == null ? "n/a" : String.format(Locale.ROOT, "%.6f", d.rotDegPerM()), d.segments());
    }

    private static void row(StringBuilder sb, String name, EvaluationReport.Stats s, double k) {
        if (s.n() == 0) {
            sb.append(String.format(Locale.ROOT, "%-16s %12s%n", name, "(no values)"));
            return;
        }
        sb.append(String.format(Locale.ROOT, "%-16s %12.6f %12.6f %12.6f %12.6f %12.6f %12.6f %8d%n", name,
                s.rmse() * k, s.mean() * k, s.median() * k, s.std() * k, s.min() * k, s.max() * k, s.n()));
    }

    private static String fmt(double v) {
        return v == Math.rint(v) ? String.valueOf((long) v) : String.valueOf(v);
    }
}
