package org.trajeval.core.eval;

import java.util.List;
import org.trajeval.core.align.Alignment;
import org.trajeval.core.align.AlignmentModel;
import org.trajeval.core.align.AlignmentTransform;
import org.trajeval.core.report.EvaluationReport;
import org.trajeval.core.traj.PositionColumns;

/**
 * The alignment of {@link ColumnarEvaluator} and its check ({@link AlignmentCheck}), with their
 * independent passes over the poses side by side when a second thread is allowed: first the
 * centroids of the estimate and of the reference positions (one sum each), then the fit's
 * covariance pass beside the reference's principal spreads and whatever the caller has to do
 * meanwhile (allocate the error arrays). Each pass is the serial one, whole and in index order,
 * so the transform and the warnings are the same bits on any number of threads.
 *
 * @param transform the fitted alignment
 * @param warnings the check's warnings, possibly none
 */
record ColumnarAlignment(AlignmentTransform transform, List<EvaluationReport.Warning> warnings) {

    /**
     * @param beside work run beside the fit's covariance pass (on the other thread when there is one)
     * @throws org.trajeval.core.InputException as {@link Alignment#fit} does
     */
    static ColumnarAlignment fit(AssociatedColumns pairs, EvaluationOptions o, boolean planar, String estName,
            Parallelism par, Runnable beside) {
        AlignmentModel model = o.alignment();
        int m = pairs.size();
        int n = Alignment.pairsUsed(o.nToAlign(), m);
        PositionColumns ref = pairs.reference();
        PositionColumns est = pairs.estimate();
        double[][] means = new double[2][];
        if (Alignment.usesCentroids(model)) {
            par.all(() -> means[0] = est.centroid(n), () -> means[1] = ref.centroid(n));
        }
        AlignmentTransform[] tf = new AlignmentTransform[1];
        double[][] spreads = new double[1][];
        par.all(() -> tf[0] = Alignment.fit(model, pairs, o.nToAlign(), estName, means[0], means[1]), () -> {
            if (AlignmentCheck.needsSpreads(model, n)) {
                spreads[0] = AlignmentCheck.principalSpreads(ref, n, means[1]);
            }
            beside.run();
        });
        // the check reads the spreads of min(posesUsed, m) poses: n for se3/sim3, the only models that need them
        return new ColumnarAlignment(tf[0], AlignmentCheck.check(tf[0], ref, est, m, planar,
                tf[0].posesUsed() == n ? spreads[0] : null));
    }
}
