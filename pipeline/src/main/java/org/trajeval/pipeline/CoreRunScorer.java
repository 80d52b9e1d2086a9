package org.trajeval.pipeline;

import java.util.Locale;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.assoc.AssociationMethod;
import org.trajeval.core.eval.Convention;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.eval.Evaluator;
import org.trajeval.core.io.LoadedTrajectory;
import org.trajeval.core.io.ReadOptions;
import org.trajeval.core.io.TrajectoryReader;
import org.trajeval.core.metric.RpeUnit;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PlanarTrajectory;

/**
 * The real scorer: {@link TrajectoryReader} for both files (format auto-detected, size limited)
 * and {@link Evaluator} with the run's settings on top of the convention's preset (lesson by
 * default).
 */
public final class CoreRunScorer implements RunScorer {
    private final long maxFileBytes;

    /** @param maxFileBytes largest accepted trajectory file (bytes) */
    public CoreRunScorer(long maxFileBytes) {
        this.maxFileBytes = maxFileBytes;
    }

    @Override
    public EvaluationReport score(RunJob job) {
        ReadOptions read = ReadOptions.defaults().withLimits(maxFileBytes, ReadOptions.DEFAULT_MAX_POSES);
        LoadedTrajectory ref = named(TrajectoryReader.read(job.reference(), read), job);
        LoadedTrajectory est = named(TrajectoryReader.read(job.estimate(), read), job);
        boolean planar = ref.trajectory() instanceof PlanarTrajectory && est.trajectory() instanceof PlanarTrajectory;
        return Evaluator.evaluate(ref, est, options(job.settings(), planar));
    }

    /**
     * The report names an input by bundle and file ({@code run1.pair/run1.gt.csv}), not by its
     * path under processing/, which no longer exists once the bundle has moved on.
     */
    private static LoadedTrajectory named(LoadedTrajectory t, RunJob job) {
        String name = job.source() + "/" + java.nio.file.Paths.get(t.source()).getFileName();
        return new LoadedTrajectory(name, t.format(), t.formatReason(), t.trajectory(), t.sha256(),
                t.indexTimestamps());
    }

    /** As {@link #options(MetricSettings, boolean)} for planar data. */
    static EvaluationOptions options(MetricSettings s) {
        return options(s, true);
    }

    /**
     * @return the evaluation options of the settings: the convention's preset for the data
     *     (lesson: se2 for planar, se3 for SE(3) data), then each given setting
     */
    static EvaluationOptions options(MetricSettings s, boolean planarData) {
        Convention convention = s.convention() == null ? Convention.LESSON
                : Convention.valueOf(s.convention().toUpperCase(Locale.ROOT));
        EvaluationOptions o = EvaluationOptions.preset(convention, planarData);
        if (s.alignment() != null) {
            o = o.withAlignment(AlignmentModel.valueOf(s.alignment().toUpperCase(Locale.ROOT)));
        }
        if (s.association() != null) {
            o = o.withAssociation(AssociationMethod.valueOf(s.association().toUpperCase(Locale.ROOT)));
        }
        if (s.maxDiffS() != null) {
            o = o.withMaxDiffS(s.maxDiffS());
        }
        if (s.rpeDelta() != null || s.rpeUnit() != null) {
            RpeUnit unit = s.rpeUnit() == null ? o.rpeUnit() : switch (s.rpeUnit()) {
                case "s" -> RpeUnit.SECONDS;
                case "frames" -> RpeUnit.FRAMES;
                default -> RpeUnit.METRES;
            };
            o = o.withRpe(s.rpeDelta() == null ? o.rpeDelta() : s.rpeDelta(), unit);
        }
        return o;
    }
}
