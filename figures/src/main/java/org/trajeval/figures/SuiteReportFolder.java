package org.trajeval.figures;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.trajeval.core.io.OutputGuard;
import org.trajeval.core.protocol.ManifestParser;
import org.trajeval.core.protocol.MethodSpec;
import org.trajeval.core.protocol.SequenceSpec;
import org.trajeval.core.protocol.SuiteManifest;
import org.trajeval.core.protocol.SuiteRunner;
import org.trajeval.core.report.SuiteReportFiles;

/**
 * The report folder of a suite, as {@code trajeval suite} and {@code trajeval-spark suite} write it:
 * report.json, runs.csv, methods.csv, comparisons.csv, report.html and, with three or more methods,
 * one average-rank diagram per metric. Every file is written atomically.
 */
public final class SuiteReportFolder {
    /** The files always written. */
    public static final List<String> FILES = List.of(SuiteReportFiles.JSON, SuiteReportFiles.RUNS_CSV,
            SuiteReportFiles.METHODS_CSV, SuiteReportFiles.COMPARISONS_CSV, SuiteHtml.FILE);

    private SuiteReportFolder() {
    }

    /**
     * Refuses an output folder whose files would replace the manifest or a trajectory it names
     * (references, and each method's estimate of every sequence and seed).
     *
     * @param manifest the suite's manifest
     * @param out the report folder
     * @param option the option naming the folder in the refusal ({@code --out})
     * @throws org.trajeval.core.InputException when an output would replace an input, or the manifest is bad
     */
    public static void refuseToReplaceInputs(Path manifest, Path out, String option) {
        for (String name : FILES) {
            OutputGuard.refuseInputs(out.resolve(name), option, List.of(manifest));
        }
        List<Path> trajectories = inputsOf(manifest);
        for (String name : FILES) {
            OutputGuard.refuseInputs(out.resolve(name), option, trajectories);
        }
    }

    /** Writes the report's tables, its page and its rank diagrams into {@code out}. */
    public static void write(SuiteRunner.Result result, Path out) {
        SuiteReportFiles.write(result.report(), out);
        SuiteHtml.write(result.report(), result.plots(), out);
        RankDiagramSvg.writeAll(result.report(), out);
    }

    /** @return the manifest and every trajectory it names, resolved against the manifest's folder */
    private static List<Path> inputsOf(Path manifest) {
        SuiteManifest m = new ManifestParser().read(manifest);
        Path base = manifest.toAbsolutePath().getParent();
        List<Path> inputs = new ArrayList<>(List.of(manifest));
        Set<Long> seeds = new TreeSet<>(m.seeds());
        m.methods().forEach(method -> seeds.addAll(method.seeds()));
        for (SequenceSpec s : m.sequences()) {
            inputs.add(base.resolve(s.reference()));
            for (MethodSpec method : m.methods()) {
                for (long seed : seeds) {
                    inputs.add(base.resolve(method.estimateFor(s.id(), seed)));
                }
            }
        }
        return inputs;
    }
}
