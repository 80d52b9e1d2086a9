package org.trajeval.figures;

import java.util.EnumSet;
import java.util.Locale;
import java.util.Set;

/** File formats a figure is written in: SVG and PDF (vector, for papers), PNG (raster, for pages). */
public enum FigureFormat {
    SVG,
    PNG,
    PDF;

    /** What {@code --plot} writes when no format is given. */
    public static final Set<FigureFormat> DEFAULT = EnumSet.of(SVG, PNG);

    /** @return the file extension, e.g. {@code "pdf"} */
    public String extension() {
        return name().toLowerCase(Locale.ROOT);
    }

    /**
     * Reads a comma list such as {@code svg,png,pdf} (any case, blanks ignored).
     *
     * @throws IllegalArgumentException naming the first word that is no format (front ends turn it
     *     into their usage error)
     */
    public static Set<FigureFormat> parseList(String text) {
        Set<FigureFormat> out = EnumSet.noneOf(FigureFormat.class);
        for (String w : text.split(",", -1)) {
            String t = w.trim().toUpperCase(Locale.ROOT);
            FigureFormat f = null;
            for (FigureFormat c : values()) {
                if (c.name().equals(t)) {
                    f = c;
                }
            }
            if (f == null) {
                throw new IllegalArgumentException("expected a comma list of svg, png and pdf, found \"" + text + "\"");
            }
            out.add(f);
        }
        return out;
    }
}
