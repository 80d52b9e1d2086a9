package org.trajeval.core.eval;

import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.assoc.AssociatedPoses;
import org.trajeval.core.metric.AteResult;
import org.trajeval.core.metric.DriftResult;
import org.trajeval.core.metric.RpeResult;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PoseSequence;

/**
 * Everything one evaluation produced: the report and the per-pose data behind it (for plots).
 *
 * @param report the report (the one report model)
 * @param associated the associated poses before alignment
 * @param reference the reference poses the metrics used (projected when asked)
 * @param alignedEstimate the estimate poses after alignment (projected when asked)
 * @param alignment the fitted transform
 * @param ate per-pose ATE
 * @param rpe per-pair RPE
 * @param drift drift, or {@code null}
 */
public record Evaluation(EvaluationReport report, AssociatedPoses associated, PoseSequence reference,
        PoseSequence alignedEstimate, AlignmentTransform alignment, AteResult ate, RpeResult rpe, DriftResult drift) {

    /** @return statistics of |T_ref^-1 T_est - I| per pose (evo's "full" APE) */
    public org.trajeval.core.stats.ErrorStatistics ateFull() {
        return ate.full();
    }

    /** @return statistics of |E_ij - I| per pair (evo's "full" RPE) */
    public org.trajeval.core.stats.ErrorStatistics rpeFull() {
        return rpe.full();
    }
}
