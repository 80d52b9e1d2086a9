package org.trajeval.cli;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.report.ResultSet;
import org.trajeval.core.stats.Interval;
import org.trajeval.core.stats.PairedTInterval;

/**
 * {@code trajeval res}'s tables: per error kind one row per saved result (the statistics as the
 * result stored them; rotations in deg), then, for names given to several results (the seeds of
 * one method), the mean RMSE over them with its t-interval. Four renderings: aligned text, CSV
 * (one long table, SI keys), Markdown and LaTeX (booktabs).
 */
final class ResTable {
    /** Output formats. */
    enum Format { TABLE, CSV, MARKDOWN, LATEX }

    private static final String[] STATS = {"rmse", "mean", "median", "std", "min", "max"};

    private ResTable() {
    }

    static String render(List<ResultSet> results, Format format, double level) {
        if (format == Format.CSV) {
            return csv(results);
        }
        StringBuilder sb = new StringBuilder();
        for (ResultSet.Kind k : ResultSet.Kind.values()) {
            List<List<String>> rows = new ArrayList<>();
            double f = k.rotation() ? 180.0 / Math.PI : 1.0;
            for (ResultSet r : results) {
                ResultSet.Errors e = r.of(k);
                if (e == null || e.stats().n() == 0) {
                    continue;
                }
                List<String> row = new ArrayList<>(List.of(r.name(), r.origin()));
                for (Double v : values(e.stats())) {
                    row.add(num(v == null ? null : v * f));
                }
                row.add(Long.toString(e.stats().n()));
                rows.add(row);
            }
            if (rows.isEmpty()) {
                continue;
            }
            String title = k.rotation() ? k.label().replace("(rad)", "(deg)") : k.label();
            table(sb, format, title, List.of("result", "from", "rmse", "mean", "median", "std", "min", "max", "n"),
                    rows);
            List<List<String>> spread = spread(results, k, f, level);
            if (!spread.isEmpty()) {
                String pct = new java.math.BigDecimal(Double.toString(100 * level)).stripTrailingZeros()
                        .toPlainString();
                table(sb, format, title + ": RMSE over the results of one name (seeds)", List.of("name", "results",
                        "mean rmse", "sd", "t-interval " + pct + " %", "min rmse", "max rmse"), spread);
            }
        }
        return sb.toString();
    }

    private static List<List<String>> spread(List<ResultSet> results, ResultSet.Kind k, double f, double level) {
        Map<String, List<Double>> byName = new LinkedHashMap<>();
        for (ResultSet r : results) {
            ResultSet.Errors e = r.of(k);
            if (e != null && e.stats().rmse() != null) {
                byName.computeIfAbsent(r.name(), x -> new ArrayList<>()).add(e.stats().rmse() * f);
            }
        }
        List<List<String>> rows = new ArrayList<>();
        for (Map.Entry<String, List<Double>> g : byName.entrySet()) {
            double[] v = g.getValue().stream().mapToDouble(Double::doubleValue).toArray();
            if (v.length < 2) {
                continue;
            }
            Interval ci = PairedTInterval.of(v, level); // the t-interval of a mean: d = the RMSEs themselves
            double mean = ci.estimate();
            double ss = 0;
            double lo = Double.POSITIVE_INFINITY;
            double hi = Double.NEGATIVE_INFINITY;
            for (double d : v) {
                ss += (d - mean) * (d - mean);
                lo = Math.min(lo, d);
                hi = Math.max(hi, d);
            }
            rows.add(List.of(g.getKey(), Integer.toString(v.length), num(mean), num(Math.sqrt(ss / (v.length - 1))),
                    "[" + num(ci.lower()) + ", " + num(ci.upper()) + "]", num(lo), num(hi)));
        }
        return rows;
    }

    private static void table(StringBuilder sb, Format format, String title, List<String> header,
            List<List<String>> rows) {
        switch (format) {
            case MARKDOWN -> {
                sb.append("**").append(title).append("**\n\n| ").append(String.join(" | ", header)).append(" |\n|");
                for (int i = 0; i < header.size(); i++) {
                    sb.append(i < 2 ? " --- |" : " ---: |");
                }
                sb.append('\n');
                for (List<String> r : rows) {
                    sb.append("| ").append(String.join(" | ", r.stream().map(s -> s.replace("|", "\\|")).toList()))
                            .append(" |\n");
                }
                sb.append('\n');
            }
            case LATEX -> {
                sb.append("% ").append(title).append("\n\\begin{tabular}{ll").append("r".repeat(header.size() - 2))
                        .append("}\n\\toprule\n").append(String.join(" & ", header.stream().map(ResTable::tex)
                                .toList())).append(" \\\\\n\\midrule\n");
                for (List<String> r : rows) {
                    sb.append(String.join(" & ", r.stream().map(ResTable::tex).toList())).append(" \\\\\n");
                }
                sb.append("\\bottomrule\n\\end{tabular}\n\n");
            }
            default -> {
                int[] w = new int[header.size()];
                for (int i = 0; i < w.length; i++) {
                    w[i] = header.get(i).length();
                    for (List<String> r : rows) {
                        w[i] = Math.max(w[i], r.get(i).length());
                    }
                }
                sb.append(title).append('\n');
                line(sb, header, w);
                for (List<String> r : rows) {
                    line(sb, r, w);
                }
                sb.append('\n');
            }
        }
    }

    private static void line(StringBuilder sb, List<String> cells, int[] w) {
        for (int i = 0; i < cells.size(); i++) {
            String c = cells.get(i);
            String pad = " ".repeat(w[i] - c.length());
            sb.append(i == 0 ? "" : "  ").append(i < 2 ? c + pad : pad + c);
        }
        sb.append('\n');
    }

    private static String csv(List<ResultSet> results) {
        StringBuilder sb = new StringBuilder("name,origin,source,metric,rmse,mean,median,std,min,max,n\n");
        for (ResultSet r : results) {
            for (ResultSet.Errors e : r.errors()) {
                if (e.stats().n() == 0) {
                    continue;
                }
                sb.append(csvField(r.name())).append(',').append(r.origin()).append(',').append(csvField(r.source()))
                        .append(',').append(e.kind().key());
                for (Double v : values(e.stats())) {
                    sb.append(',').append(v == null ? "" : Double.toString(v));
                }
                sb.append(',').append(e.stats().n()).append('\n');
            }
        }
        return sb.toString();
    }

    private static Double[] values(EvaluationReport.Stats s) {
        return new Double[] {s.rmse(), s.mean(), s.median(), s.std(), s.min(), s.max()};
    }

    private static String csvField(String s) {
        return s.contains(",") || s.contains("\"") || s.contains("\n") ? "\"" + s.replace("\"", "\"\"") + "\"" : s;
    }

    private static String tex(String s) {
        StringBuilder b = new StringBuilder(s.length() + 8);
        for (char c : s.toCharArray()) {
            switch (c) {
                case '\\' -> b.append("\\textbackslash{}");
                case '&', '%', '_', '#', '$', '{', '}' -> b.append('\\').append(c);
                case '~' -> b.append("\\textasciitilde{}");
                case '^' -> b.append("\\textasciicircum{}");
                default -> b.append(c);
            }
        }
        return b.toString();
    }

    static String num(Double v) {
        return v == null || !Double.isFinite(v) ? "-" : String.format(Locale.ROOT, "%.6g", v);
    }
}
