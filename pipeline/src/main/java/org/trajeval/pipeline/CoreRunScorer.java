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
        LoadedTrajectory ref = TrajectoryReader.read(job.reference(), read);
        LoadedTrajectory est = TrajectoryReader.read(job.estimate(), read);
        return Evaluator.evaluate(ref, est, options(job.settings()));
    }

    /** @return the evaluation options of the settings: the convention's preset, then each given setting */
    static EvaluationOptions options(MetricSettings s) {
        Convention convention = s.convention() == null ? Convention.LESSON
                : Convention.valueOf(s.convention().toUpperCase(Locale.ROOT));
        EvaluationOptions o = EvaluationOptions.preset(convention);
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
