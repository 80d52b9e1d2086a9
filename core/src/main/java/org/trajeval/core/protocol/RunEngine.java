package org.trajeval.core.protocol;

import java.nio.file.Path;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.report.EvaluationReport;

/** Reads trajectories and scores one run; the suite runner takes it as a parameter so tests can fake it. */
public interface RunEngine {

    /**
     * Reads one trajectory file.
     *
     * @param file the file
     * @param options how to read it (from the run's settings)
     * @throws org.trajeval.core.InputException on a bad file
     */
    LoadedTrajectory read(Path file, ReadOptions options);

    /**
     * Scores an estimate against a reference.
     *
     * @throws org.trajeval.core.InputException when the pair cannot be scored
     */
    EvaluationReport evaluate(LoadedTrajectory reference, LoadedTrajectory estimate, EvaluationOptions options);

    /** @return the real engine: {@link TrajectoryReader} and {@link Evaluator} */
    static RunEngine standard() {
        return new RunEngine() {
            @Override
            public LoadedTrajectory read(Path file, ReadOptions options) {
                return TrajectoryReader.read(file, options);
            }

            @Override
            public EvaluationReport evaluate(LoadedTrajectory reference, LoadedTrajectory estimate,
                    EvaluationOptions options) {
                return Evaluator.evaluate(reference, estimate, options);
            }
        };
    }
}
