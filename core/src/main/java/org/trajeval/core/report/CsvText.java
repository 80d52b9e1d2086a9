package org.trajeval.core.report;

import java.util.List;

/**
 * The CSV text of the report tables (RFC 4180): fields joined by commas, a field holding a comma,
 * quote, CR or LF quoted with its quotes doubled; numbers as {@link Double#toString}, absent or
 * non-finite values as empty fields.
 */
public final class CsvText {
    private CsvText() {
    }

    /** Appends one row (fields as given, {@code null} as empty) and its newline. */
    public static void row(StringBuilder sb, List<String> fields) {
        for (int i = 0; i < fields.size(); i++) {
            if (i > 0) {
                sb.append(',');
            }
            String f = fields.get(i) == null ? "" : fields.get(i);
            if (f.indexOf(',') >= 0 || f.indexOf('"') >= 0 || f.indexOf('\n') >= 0 || f.indexOf('\r') >= 0) {
                sb.append('"').append(f.replace("\"", "\"\"")).append('"');
            } else {
                sb.append(f);
            }
        }
        sb.append('\n');
    }

    /** @return the number as {@link Double#toString}, or empty when absent or not finite */
    public static String number(Double v) {
        return v == null || !Double.isFinite(v) ? "" : Double.toString(v);
    }
}
