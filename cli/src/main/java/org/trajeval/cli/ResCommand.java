package org.trajeval.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import org.trajeval.core.report.ResultSet;
import org.trajeval.core.report.SavedResults;
import org.trajeval.figures.FigurePage;
import org.trajeval.figures.ResFigures;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code trajeval res RESULT...}: compares saved evaluation results, trajeval's and evo's. */
@Command(name = "res", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Compares saved evaluation results side by side: trajeval's (eval --save-series DIR, or "
            + "eval --out FILE.json for the summary only) and evo's --save_results zips.",
            "Give a result a name with NAME=PATH; results sharing a name are the seeds of one method and get a "
                + "line with the mean RMSE over them and its t-interval.",
            "Units: translation m, rotation deg in the tables (CSV: SI keys, rad)."},
        exitCodeListHeading = "%nExit codes:%n",
        exitCodeList = {"0:success", "1:internal error (a bug; rerun with --verbose)",
            "2:bad input (a file that is no saved result; one line names it)"})
public final class ResCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(arity = "1..*", paramLabel = "[NAME=]RESULT", description = "A --save-series folder, an eval "
            + "--out .json or an evo --save_results .zip.")
    List<String> inputs;

    @Option(names = "--format", paramLabel = "table|csv|markdown|latex", defaultValue = "table",
            converter = ResCommand.FormatConverter.class, description = "Table format (default: ${DEFAULT-VALUE}).")
    ResTable.Format format;

    @Option(names = "--plot", paramLabel = "DIR", description = "Draw box plots of each error side by side and the "
            + "errors over time overlaid into DIR (SVG, PNG, index.html).")
    Path plotDir;

    @Option(names = "--plot-format", paramLabel = "svg,png,pdf", defaultValue = "svg,png",
            converter = PlotOptions.FormatsConverter.class, description = "Files of each figure of --plot (default: "
            + "${DEFAULT-VALUE}); pdf: one vector page per figure, for papers.")
    java.util.Set<org.trajeval.figures.FigureFormat> formats;

    @Option(names = "--confidence", paramLabel = "LEVEL", defaultValue = "0.95",
            description = "Level of the t-interval over seeds (default: ${DEFAULT-VALUE}).")
    double level;

    @Option(names = "--verbose", description = "Print stack traces of errors.")
    boolean verbose;

    /** Reads table|csv|markdown|latex, any case. */
    static final class FormatConverter implements picocli.CommandLine.ITypeConverter<ResTable.Format> {
        @Override
        public ResTable.Format convert(String v) {
            for (ResTable.Format f : ResTable.Format.values()) {
                if (f.name().equalsIgnoreCase(v.trim())) {
                    return f;
                }
            }
            throw new picocli.CommandLine.TypeConversionException("expected table|csv|markdown|latex, found \""
                    + v + "\"");
        }
    }

    @Override
    public Integer call() {
        if (!(level > 0 && level < 1)) {
            throw UsageProblem.of("--confidence must be in (0, 1), found " + level);
        }
        List<ResultSet> results = new ArrayList<>();
        FigurePage.Progress bar = ProgressBar.counter(spec.commandLine().getErr(), "results");
        for (int i = 0; i < inputs.size(); i++) {
            String in = inputs.get(i);
            int eq = in.indexOf('=');
            boolean named = eq > 0 && !java.nio.file.Files.exists(Path.of(in));
            results.add(SavedResults.read(Path.of(named ? in.substring(eq + 1) : in), named ? in.substring(0, eq)
                    : null));
            bar.done(i + 1, inputs.size());
        }
        PrintWriter out = spec.commandLine().getOut();
        out.print(ResTable.render(results, format, level));
        out.flush();
        if (plotDir != null) {
            StringBuilder list = new StringBuilder("<ul>\n");
            for (ResultSet r : results) {
                list.append("<li><b>").append(FigurePage.esc(r.name())).append("</b> (").append(r.origin())
                        .append("): <code>").append(FigurePage.esc(r.source())).append("</code> &mdash; ")
                        .append(FigurePage.esc(r.description())).append("</li>\n");
            }
            list.append("</ul>\n<div class=\"scroll\"><pre>").append(FigurePage.esc(ResTable.render(results,
                    ResTable.Format.TABLE, level))).append("</pre></div>\n");
            FigurePage.write("Saved results compared", list.toString(), ResFigures.of(results), plotDir, formats,
                    ProgressBar.counter(spec.commandLine().getErr(), "figures"));
        }
        return ExitCodes.OK;
    }
}
