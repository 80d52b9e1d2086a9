package org.trajeval.pipeline;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Comparator;
import java.util.stream.Stream;
import org.trajeval.core.report.SavedEvaluation;
import org.trajeval.figures.EvalPlotPage;
import org.trajeval.figures.FigurePage;
import org.trajeval.figures.PlotPlane;

/**
 * A run's figures ({@code plot: true} in run.yaml): the page {@code trajeval eval --plot} writes
 * ({@link EvalPlotPage}: every figure as SVG and PNG, {@code index.html}), drawn into a hidden
 * draft folder beside the reports ({@code reports/.RUN_ID.plots.NNN}) and moved into place
 * ({@code reports/RUN_ID.plots/}, {@code RUN_ID.vN.plots/} for the N-th content) by one rename
 * when the report is committed: a reader sees no folder or a complete one.
 */
final class RunPlots {
    private RunPlots() {
    }

    /**
     * Draws the figures into a new draft folder.
     *
     * @return the draft folder
     * @throws IllegalStateException when the series are missing (a scorer that keeps none)
     * @throws UncheckedIOException when the folder cannot be written
     */
    static Path draft(SavedEvaluation saved, Path reportsDir, String runId) {
        if (saved.series() == null) {
            throw new IllegalStateException("the scorer kept no per-pose series to draw");
        }
        Path dir;
        try {
            dir = Files.createTempDirectory(reportsDir, "." + runId + ".plots.");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot create a draft folder in " + reportsDir, e);
        }
        try {
            EvalPlotPage.write(saved, PlotPlane.AUTO, dir, FigurePage.Progress.none());
            return dir;
        } catch (RuntimeException e) {
            discard(dir);
            throw e;
        }
    }

    /**
     * Moves a draft to its place, replacing an earlier folder of the same name (a retried run).
     *
     * @throws IOException when the move fails (the draft is left for {@link #discard})
     */
    static void publish(Path draft, Path target) throws IOException {
        if (Files.exists(target)) {
            Path old = Files.createTempDirectory(target.getParent(), "." + target.getFileName() + ".old.");
            Files.move(target, old.resolve("x"), StandardCopyOption.ATOMIC_MOVE);
            discard(old);
        }
        try {
            Files.move(draft, target, StandardCopyOption.ATOMIC_MOVE);
        } catch (FileAlreadyExistsException e) {
            throw new IOException(target + " appeared while the figures were moved into place", e);
        }
    }

    /** Deletes a draft (best effort: a leftover hidden folder harms nobody). */
    static void discard(Path dir) {
        if (dir == null || !Files.exists(dir)) {
            return;
        }
        try (Stream<Path> s = Files.walk(dir)) {
            s.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException | UncheckedIOException e) {
            // left behind: hidden, and named as a draft
        }
    }
}
