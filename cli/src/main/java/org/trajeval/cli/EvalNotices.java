package org.trajeval.cli;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.trajeval.core.InputException;
import org.trajeval.core.InputProblem;
import org.trajeval.core.assoc.OverlapPolicy;
import org.trajeval.core.eval.EvaluationOptions;
import org.trajeval.core.report.EvaluationReport;

/**
 * What an eval did differently from what was asked. The report's warnings say it for every front
 * end ({@code n_to_align_clamped}, {@code no_rpe_pairs}, printed with the table); here, an RPE
 * horizon longer than the trajectory (no pair at all) is refused under {@code --overlap strict},
 * which asks for every requested quantity or nothing.
 */
final class EvalNotices {
    private EvalNotices() {
    }

    /**
     * @param requestedNToAlign the --n-to-align given, or {@code null}
     * @return the warning lines to print on stderr (none when all went as asked)
     * @throws InputException ({@link InputProblem#TOO_FEW_POSES}) for an RPE without pairs under strict overlap
     */
    static List<String> of(EvaluationReport report, EvaluationOptions options, Integer requestedNToAlign) {
        List<String> notes = new ArrayList<>();
        EvaluationReport.Rpe rpe = report.rpe();
        if (rpe != null && rpe.pairs() == 0) {
            String what = String.format(Locale.ROOT, "no RPE pair: --rpe-delta %s %s is longer than the associated "
                    + "trajectory, so the RPE rows are empty; choose a shorter --rpe-delta",
                    plain(rpe.delta()), rpe.unit());
            if (options.overlap() == OverlapPolicy.STRICT) {
                throw new InputException(null, 0, "--rpe-delta", InputProblem.TOO_FEW_POSES,
                        what + " (refused under --overlap strict)", null);
            }
        }
        return notes;
    }

    private static String plain(double v) {
        return v == Math.rint(v) && Math.abs(v) < 1e15 ? String.valueOf((long) v) : String.valueOf(v);
    }
}
