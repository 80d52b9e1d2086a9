package org.trajeval.cli;

import java.nio.file.Path;
import picocli.CommandLine.Option;

/** {@code eval}'s switches for figures and saved series. */
final class PlotOptions {
    @Option(names = "--plot", paramLabel = "DIR", description = "Draw the evaluation into DIR: trajectories "
            + "(estimate coloured by ATE), ATE and RPE over time, histograms, KITTI drift per length with --drift; "
            + "every figure as SVG and PNG, and DIR/index.html with the numbers.")
    Path plotDir;

    @Option(names = "--plot-plane", paramLabel = "auto|xy|xz|yz", defaultValue = "auto",
            converter = PlotOptions.PlaneConverter.class, description = "Plane of the trajectory plot (default: "
            + "${DEFAULT-VALUE}: the two axes of largest extent, x-z for KITTI's camera frame).")
    org.trajeval.figures.PlotPlane plane;

    @Option(names = "--plot-format", paramLabel = "svg,png,pdf", defaultValue = "svg,png",
            converter = PlotOptions.FormatsConverter.class, description = "Files of each figure of --plot (default: "
            + "${DEFAULT-VALUE}); pdf: one vector page per figure (PDF 1.4, Helvetica), for papers.")
    java.util.Set<org.trajeval.figures.FigureFormat> formats;

    @Option(names = "--save-series", paramLabel = "DIR", description = "Save the evaluation into DIR: report.json, "
            + "poses.csv.gz (time, reference and aligned estimate positions (m), ATE (m, rad) per pose) and "
            + "pairs.csv.gz (RPE (m, rad) per pair); pandas reads each with pd.read_csv. trajeval res reads DIR.")
    Path seriesDir;

    /** Reads auto|xy|xz|yz, any case. */
    static final class PlaneConverter implements picocli.CommandLine.ITypeConverter<org.trajeval.figures.PlotPlane> {
        @Override
        public org.trajeval.figures.PlotPlane convert(String v) {
            for (org.trajeval.figures.PlotPlane p : org.trajeval.figures.PlotPlane.values()) {
                if (p.name().equalsIgnoreCase(v.trim())) {
                    return p;
                }
            }
            throw new picocli.CommandLine.TypeConversionException("expected auto|xy|xz|yz, found \"" + v + "\"");
        }
    }

    /** Reads a comma list of svg, png and pdf. */
    static final class FormatsConverter
            implements picocli.CommandLine.ITypeConverter<java.util.Set<org.trajeval.figures.FigureFormat>> {
        @Override
        public java.util.Set<org.trajeval.figures.FigureFormat> convert(String v) {
            try {
                return org.trajeval.figures.FigureFormat.parseList(v);
            } catch (IllegalArgumentException e) {
                throw new picocli.CommandLine.TypeConversionException(e.getMessage());
            }
        }
    }

    /** @return true when the per-pose data is needed */
    boolean wanted() {
        return plotDir != null || seriesDir != null;
    }
}
