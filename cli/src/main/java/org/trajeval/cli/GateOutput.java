package org.trajeval.cli;

import java.io.PrintWriter;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.protocol.RegressionGate.Finding;
import org.trajeval.core.protocol.RegressionGate.Verdict;
import org.trajeval.core.report.SuiteReport.Paired;

/** The gate's findings as a terminal table, a Markdown summary and JUnit XML. */
final class GateOutput {
    private GateOutput() {
    }

    /** @return "PASS" or "FAIL (k regressions)" */
    static String headline(List<Finding> fs) {
        long k = fs.stream().filter(f -> f.verdict() == Verdict.REGRESSION).count();
        return k == 0 ? "PASS" : "FAIL (" + k + (k == 1 ? " regression)" : " regressions)");
    }

    static void table(List<Finding> fs, double confidence, PrintWriter out) {
        out.printf(Locale.ROOT, "%-12s %-18s %3s %11s %11s %9s %12s %11s %s%n", "method", "metric", "n", "baseline",
                "candidate", "change", "bound", "margin", "verdict");
        for (Finding f : fs) {
            out.printf(Locale.ROOT, "%-12s %-18s %3d %11s %11s %9s %12s %11s %s%n", f.method(), f.metric(), f.n(),
                    num(f.baselineMean()), num(f.candidateMean()), change(f),
                    num(f.bound()), (f.higherIsBetter() ? "-" : "+") + num(f.margin()),
                    f.verdict().name().toLowerCase(Locale.ROOT));
        }
        out.println("gate: " + headline(fs) + "; rule: a metric regresses when the one-sided bound of the mean "
                + "paired difference (candidate - baseline; " + pct(confidence) + " shared by the " + fs.size()
                + " rows, Bonferroni) is beyond the margin = tolerance x |baseline mean| (lower bound > +margin; "
                + "the score: upper bound < -margin)");
    }

    static String markdown(List<Finding> fs, double confidence, String baseline, String candidate) {
        StringBuilder b = new StringBuilder();
        b.append("### trajeval gate: ").append(headline(fs)).append("\n\n");
        b.append("Baseline `").append(baseline).append("`, candidate `").append(candidate).append("`; one-sided bound of the mean paired difference (")
                .append(pct(confidence)).append(" shared by the ").append(fs.size())
                .append(" rows, Bonferroni) against tolerance x baseline.\n\n");
        b.append("| method | metric | n | baseline | candidate | change | tolerance | verdict |\n");
        b.append("|---|---|---:|---:|---:|---:|---:|---|\n");
        for (Finding f : fs) {
            b.append("| ").append(md(f.method())).append(" | ").append(md(f.metric())).append(" | ").append(f.n())
                    .append(" | ").append(num(f.baselineMean())).append(" | ")
                    .append(num(f.candidateMean())).append(" | ").append(change(f)).append(" | ")
                    .append(String.format(Locale.ROOT, "%.1f %%", 100 * f.tolerance())).append(" | ")
                    .append(f.verdict() == Verdict.REGRESSION ? "**regression**"
                            : f.verdict().name().toLowerCase(Locale.ROOT))
                    .append(" |\n");
        }
        return b.toString();
    }

    /**
     * JUnit XML: one test suite per method; per metric one test case carrying the gate's verdict, and
     * one per (metric, sequence) that fails when the metric regressed and that sequence alone is worse
     * than the tolerance (so a CI page shows which sequences drive a regression).
     */
    static String junit(List<Finding> fs) {
        StringBuilder b = new StringBuilder("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
        long tests = fs.stream().mapToLong(f -> 1 + f.perSequence().size()).sum();
        long failures = 0;
        StringBuilder suites = new StringBuilder();
        for (String method : fs.stream().map(Finding::method).distinct().toList()) {
            List<Finding> mine = fs.stream().filter(f -> f.method().equals(method)).toList();
            StringBuilder cases = new StringBuilder();
            int t = 0;
            int fail = 0;
            for (Finding f : mine) {
                t++;
                cases.append("    <testcase classname=\"trajeval.gate.").append(xml(method)).append("\" name=\"")
                        .append(xml(f.metric())).append("\">");
                if (f.verdict() == Verdict.REGRESSION) {
                    fail++;
                    cases.append("<failure message=\"").append(xml(f.metric() + " regressed " + change(f)
                            + " (tolerance " + String.format(Locale.ROOT, "%.1f%%", 100 * f.tolerance()) + ")"))
                            .append("\"/>");
                } else if (f.verdict() == Verdict.INCONCLUSIVE) {
                    cases.append("<skipped message=\"fewer than 2 paired sequences\"/>");
                }
                cases.append("</testcase>\n");
                for (Paired p : f.perSequence()) {
                    t++;
                    cases.append("    <testcase classname=\"trajeval.gate.").append(xml(method)).append("\" name=\"")
                            .append(xml(f.metric() + " " + p.sequence())).append("\">");
                    if (f.verdict() == Verdict.REGRESSION && f.sequenceWorse(p)) {
                        fail++;
                        cases.append("<failure message=\"").append(xml("baseline " + num(p.b())
                                + ", candidate " + num(p.a()))).append("\"/>");
                    }
                    cases.append("</testcase>\n");
                }
            }
            failures += fail;
            suites.append("  <testsuite name=\"").append(xml(method)).append("\" tests=\"").append(t)
                    .append("\" failures=\"").append(fail).append("\">\n").append(cases).append("  </testsuite>\n");
        }
        b.append("<testsuites name=\"trajeval gate\" tests=\"").append(tests).append("\" failures=\"")
                .append(failures).append("\">\n").append(suites).append("</testsuites>\n");
        return b.toString();
    }

    private static String num(double v) {
        return Double.isFinite(v) ? String.format(Locale.ROOT, "%.4g", v) : "-";
    }

    private static String change(Finding f) {
        double c = f.relativeChange();
        return Double.isFinite(c) ? String.format(Locale.ROOT, "%+.1f%%", 100 * c) : "-";
    }

    private static String pct(double c) {
        return String.format(Locale.ROOT, "%.0f%%", 100 * c);
    }

    /** Escapes text for XML attributes: markup characters and control characters (as U+FFFD). */
    static String xml(String s) {
        StringBuilder b = new StringBuilder(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '&' -> b.append("&amp;");
                case '<' -> b.append("&lt;");
                case '>' -> b.append("&gt;");
                case '"' -> b.append("&quot;");
                case '\'' -> b.append("&apos;");
                default -> b.append(c < 0x20 && c != '\t' ? '\uFFFD' : c);
            }
        }
        return b.toString();
    }

    /** Escapes a Markdown table cell. */
    private static String md(String s) {
        return s.replace("|", "\\|").replace("\n", " ");
    }
}
