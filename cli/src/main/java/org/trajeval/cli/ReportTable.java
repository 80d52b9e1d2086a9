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
        // KITTI poses without times files are stamped by index: times are frames, not seconds
        String u = "frames".equals(r.timeBase()) ? "frames" : "s";
        sb.append(String.format(Locale.ROOT, "convention %s; association %s: %d matched, %d estimate poses dropped",
                r.convention(), a.method(), a.matched(), a.dropped()));
        if (!"interpolate".equals(a.method())) {
            sb.append(String.format(Locale.ROOT, ", max diff %.4g %s", a.maxDiffS(), u));
        }
        if (a.tOffsetS() != 0.0) {
            sb.append(String.format(Locale.ROOT, ", offset %.4g %s", a.tOffsetS(), u));
        }
        if (a.tOffsetAuto() != null) {
            sb.append(String.format(Locale.ROOT, " (auto: correlation peak %.4g +- %.2g %s, refined on ATE)",
                    a.tOffsetAuto().correlationS(), a.tOffsetAuto().uncertaintyS(), u));
        }
        sb.append(String.format(Locale.ROOT, "%n           reference max gap h = %.4g %s", a.maxGapS(), u));
        if (a.gapLimitS() != null) {
            sb.append(String.format(Locale.ROOT, " (interpolation bridges gaps up to %.4g %s)", a.gapLimitS(), u));
        }
        if (a.interpErrorBoundM() != null) {
            sb.append(String.format(Locale.ROOT, ", interpolation error bound A_max h^2/8 = %.3g m (A_max %.3g m/s^2)",
                    a.interpErrorBoundM(), a.aMaxMps2()));
        }
        sb.append(System.lineSeparator());
        if (a.droppedInGaps() > 0) {
            sb.append(String.format(Locale.ROOT, "           %d estimate poses dropped inside %d reference gaps longer "
                    + "than %.4g %s:", a.droppedInGaps(), a.gaps().size(), a.gapLimitS(), u));
            int shown = 0;
            for (EvaluationReport.Gap g : a.gaps()) {
                if (shown++ == 3) {
                    sb.append(" ...");
                    break;
                }
                sb.append(String.format(Locale.ROOT, " %d in [%.3f, %.3f] %s (%.3f %s)%s", g.dropped(), g.startS(),
                        g.endS(), u, g.lengthS(), u, shown < Math.min(3, a.gaps().size()) ? ";" : ""));
            }
            sb.append(System.lineSeparator());
        }
        EvaluationReport.CoverageInfo c = r.coverage();
        if (c != null) {
            sb.append(String.format(Locale.ROOT, "coverage   %.1f %% of the reference's %.3f %s; longest stretch without "
                    + "an estimate %.3f %s (from %.3f %s)%n", 100.0 * c.fraction(), c.referenceSpanS(), u,
                    c.longestGapS(), u, c.longestGapStartS(), u));
        }
        EvaluationReport.AlignmentInfo al = r.alignment();
        if ("none".equals(al.model())) {
            sb.append(String.format(Locale.ROOT, "alignment  none%n"));
        } else {
            double[][] rot = al.rotation();
            double yaw = Math.toDegrees(Math.atan2(rot[1][0], rot[0][0]));
            sb.append(String.format(Locale.ROOT, "alignment  %s on %d poses: translation (%.4f, %.4f, %.4f) m, yaw "
                    + "%.4f deg, scale %.6f%n", al.model(), al.posesUsed(), al.translationM()[0], al.translationM()[1],
                    al.translationM()[2], yaw, al.scale()));
        }
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
        if (r.extra() != null) {
            EvaluationReport.Extra x = r.extra();
            row(sb, "trans x (m)", x.transXM(), 1.0);
            row(sb, "trans y (m)", x.transYM(), 1.0);
            row(sb, "trans z (m)", x.transZM(), 1.0);
            row(sb, "heading (deg)", x.headingRad(), 180.0 / Math.PI);
            row(sb, "speed (m/s)", x.speedMps(), 1.0);
        }
        EvaluationReport.Rpe rpe = r.rpe();
        sb.append(String.format(Locale.ROOT, "RPE: delta %s %s, %s, chosen on the %s: %d pairs", fmt(rpe.delta()),
                rpe.unit(), "all_pairs".equals(rpe.pairSelection()) ? "every start pose" : "consecutive pairs",
                rpe.pairsFrom(), rpe.pairs()));
        if (rpe.meanHorizonS() != null) {
            sb.append(String.format(Locale.ROOT, ", mean horizon %.4g %s / %.4g m", rpe.meanHorizonS(), u,
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

    /** KITTI's units: % of the segment length and deg per 100 m. */
    private static String drift(EvaluationReport.Drift d) {
        if (d.segments() == 0) {
            double shortest = d.perLength().stream().mapToDouble(EvaluationReport.DriftAtLength::lengthM).min()
                    .orElse(Double.NaN);
            return String.format(Locale.ROOT, "drift: n/a: the reference path is %.1f m long, shorter than the shortest "
                    + "segment length %.4g m%n", d.pathLengthM() == null ? Double.NaN : d.pathLengthM(), shortest);
        }
        return String.format(Locale.ROOT, "drift: %s %% translation, %s deg/100 m rotation over %d segments%n",
                d.transPct() == null ? "n/a" : String.format(Locale.ROOT, "%.4f", d.transPct()),
                d.rotDegPer100m() == null ? "n/a" : String.format(Locale.ROOT, "%.4f", d.rotDegPer100m()),
                d.segments());
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
