package org.trajeval.core.report;

import org.trajeval.core.InputException;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Opens any saved result {@code trajeval res} accepts: a {@link SavedEvaluation} folder (summary
 * and series), a trajeval evaluation JSON ({@code eval --out}, summary only), or an evo
 * {@code --save_results} zip ({@link EvoResultArchive}).
 */
public final class SavedResults {
    private SavedResults() {
    }

    /**
     * @param name the name to give the result (a method name), or null for the file name
     * @throws InputException with one line naming the file when it is none of these
     */
    public static ResultSet read(Path path, String name) {
        String n = name != null ? name : stem(path);
        if (Files.isDirectory(path)) {
            return of(SavedEvaluation.read(path), path.toString(), n);
        }
        if (!Files.isRegularFile(path)) {
            throw InputException.unreadable(path + ": no such file or folder");
        }
        String lower = path.getFileName().toString().toLowerCase(Locale.ROOT);
        if (lower.endsWith(".zip")) {
            return EvoResultArchive.read(path, n);
        }
        if (lower.endsWith(".json")) {
            try {
                EvaluationReport r = ReportJson.parseEvaluation(Files.readString(path));
                if (!EvaluationReport.SCHEMA.equals(r.schema())) {
                    throw InputException.unreadable(path + ": schema " + EvaluationReport.SCHEMA
                            + " expected, found \"" + r.schema() + "\"");
                }
                return of(new SavedEvaluation(r, null), path.toString(), n);
            } catch (IOException e) {
                throw InputException.unreadable(path + ": cannot be read (" + e.getMessage() + ")", e);
            } catch (InputException e) {
                throw e.getMessage() != null && e.getMessage().startsWith(path.toString()) ? e
                        : InputException.unreadable(path + ": not a trajeval evaluation report (a suite report? "
                                + "compare reads those)", e);
            }
        }
        throw InputException.unreadable(path + ": a --save-series folder, an eval --out .json or an evo "
                + "--save_results .zip expected");
    }

    /** The result of a saved evaluation (series may be null: summary only). */
    static ResultSet of(SavedEvaluation s, String source, String name) {
        EvaluationReport r = s.report();
        EvaluationSeries.Poses p = s.series() == null ? null : s.series().poses();
        EvaluationSeries.Pairs q = s.series() == null ? null : s.series().pairs();
        List<ResultSet.Errors> e = new ArrayList<>();
        e.add(new ResultSet.Errors(ResultSet.Kind.ATE_TRANS, r.ate().transM(), p == null ? null : p.t(),
                p == null ? null : p.ateTransM()));
        e.add(new ResultSet.Errors(ResultSet.Kind.ATE_ROT, r.ate().rotRad(), p == null ? null : p.t(),
                p == null ? null : p.ateRotRad()));
        e.add(new ResultSet.Errors(ResultSet.Kind.RPE_TRANS, r.rpe().transM(), q == null ? null : q.t(),
                q == null ? null : q.rpeTransM()));
        e.add(new ResultSet.Errors(ResultSet.Kind.RPE_ROT, r.rpe().rotRad(), q == null ? null : q.t(),
                q == null ? null : q.rpeRotRad()));
        String d = "alignment " + r.alignment().model() + ", RPE delta " + r.rpe().delta() + " " + r.rpe().unit()
                + " " + r.rpe().pairSelection();
        return new ResultSet(name, source, "trajeval", d, s.series() == null ? null : s.series().timeUnit(), e,
                s.series() == null ? EvaluationSeries.Segments.NONE : s.series().segments());
    }

    private static String stem(Path p) {
        String f = p.getFileName() == null ? p.toString() : p.getFileName().toString();
        int dot = f.lastIndexOf('.');
        return dot > 0 ? f.substring(0, dot) : f;
    }
}
